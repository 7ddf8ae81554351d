// @vitest-environment jsdom
// The energy plot's series keeps up while the host computes (audit of session 20: it stayed at the
// first 10 s of a computation 96,000 s long), at a pace set by what each request costs.
import { act, cleanup, render } from "@testing-library/react";
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import type { SeriesPoint } from "../remote/protocol";
import { SERIES_REFRESH_MS, type SeriesSource, seriesDelay, useSeries } from "./useSeries";

afterEach(cleanup);
beforeEach(() => {
  vi.useFakeTimers();
  return () => vi.useRealTimers();
});

/** A source whose n-th answer spans [0, n] and is computed in no time. */
function source() {
  let calls = 0;
  const s: SeriesSource = {
    series: () => {
      calls++;
      return Promise.resolve([{ t: calls, energy: 1, collisions: calls }]);
    },
  };
  return { s, calls: () => calls };
}

function Probe({
  client,
  revision,
  busy,
  seen,
}: {
  client: SeriesSource;
  revision: number;
  busy: boolean;
  seen: SeriesPoint[][];
}) {
  seen.push(useSeries(client, revision, busy));
  return null;
}

async function flush(ms: number) {
  await act(async () => {
    await vi.advanceTimersByTimeAsync(ms);
  });
}

describe("useSeries", () => {
  it("asks once 300 ms after a change when idle, and nothing before a scene", async () => {
    const { s, calls } = source();
    const seen: SeriesPoint[][] = [];
    const view = render(<Probe client={s} revision={-1} busy={false} seen={seen} />);
    await flush(5000);
    expect(calls()).toBe(0);
    view.rerender(<Probe client={s} revision={3} busy={false} seen={seen} />);
    await flush(299);
    expect(calls()).toBe(0);
    await flush(1);
    expect(calls()).toBe(1);
    await flush(10_000);
    expect(calls()).toBe(1);
    expect(seen.at(-1)).toEqual([{ t: 1, energy: 1, collisions: 1 }]);
  });

  it("while computing, asks at once and then every SERIES_REFRESH_MS, whatever the revisions do", async () => {
    const { s, calls } = source();
    const seen: SeriesPoint[][] = [];
    const view = render(<Probe client={s} revision={3} busy={true} seen={seen} />);
    await flush(0);
    expect(calls()).toBe(1);
    // slices computed: new revisions every few ms do not restart the clock
    for (let r = 4; r < 14; r++) {
      view.rerender(<Probe client={s} revision={r} busy={true} seen={seen} />);
      await flush(SERIES_REFRESH_MS / 10);
    }
    expect(calls()).toBe(2);
    await flush(SERIES_REFRESH_MS * 3);
    expect(calls()).toBe(5);
    expect(seen.at(-1)?.[0]?.t).toBe(5);
    // done computing: one more after it settles, then quiet
    view.rerender(<Probe client={s} revision={20} busy={false} seen={seen} />);
    await flush(300);
    expect(calls()).toBe(6);
    await flush(10_000);
    expect(calls()).toBe(6);
  });

  it("while computing, a refused request does not stop the polling", async () => {
    let calls = 0;
    const s: SeriesSource = {
      series: () => {
        calls++;
        return calls === 1 ? Promise.reject(new Error("busy")) : Promise.resolve([]);
      },
    };
    const seen: SeriesPoint[][] = [];
    render(<Probe client={s} revision={3} busy={true} seen={seen} />);
    await flush(0);
    expect(calls).toBe(1);
    await flush(SERIES_REFRESH_MS * 2);
    expect(calls).toBe(3);
  });

  it("spaces requests by ten times what the last one took when that is longer", () => {
    expect(seriesDelay(5)).toBe(SERIES_REFRESH_MS);
    expect(seriesDelay(250)).toBe(2500);
  });
});
