// @vitest-environment jsdom
// useRefreshed's pacing: at most one request per interval while the inputs keep changing, except
// that a change of `urgent` (the scene itself) starts the next request at once.
import { act, cleanup, renderHook } from "@testing-library/react";
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { useRefreshed } from "./useRefreshed";

beforeEach(() => {
  vi.useFakeTimers();
});
afterEach(() => {
  cleanup();
  vi.useRealTimers();
});

describe("useRefreshed", () => {
  it("keeps the interval while only the key changes; an urgent change asks at once", async () => {
    const asked: string[] = [];
    const { rerender, result } = renderHook(
      ({ k, urgent }: { k: string; urgent: string }) =>
        useRefreshed(
          () => {
            asked.push(k);
            return Promise.resolve(k);
          },
          k,
          "none",
          1000,
          urgent,
        ),
      { initialProps: { k: "1", urgent: "doc0" } },
    );
    await act(() => vi.advanceTimersByTimeAsync(0));
    expect(asked).toEqual(["1"]);
    // Progress of a computation: new keys, same scene; the next request waits for the interval.
    rerender({ k: "2", urgent: "doc0" });
    rerender({ k: "3", urgent: "doc0" });
    await act(() => vi.advanceTimersByTimeAsync(100));
    expect(asked).toEqual(["1"]);
    await act(() => vi.advanceTimersByTimeAsync(900));
    expect(asked).toEqual(["1", "3"]);
    expect(result.current).toBe("3");
    // An edit: the scene changed; asked at once, not up to an interval later.
    rerender({ k: "4", urgent: "doc1" });
    await act(() => vi.advanceTimersByTimeAsync(0));
    expect(asked).toEqual(["1", "3", "4"]);
    expect(result.current).toBe("4");
    // After it, the interval holds again.
    rerender({ k: "5", urgent: "doc1" });
    await act(() => vi.advanceTimersByTimeAsync(500));
    expect(asked).toEqual(["1", "3", "4"]);
    await act(() => vi.advanceTimersByTimeAsync(500));
    expect(asked).toEqual(["1", "3", "4", "5"]);
  });
});
