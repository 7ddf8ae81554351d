// An edit at a time the history has not reached yet is refused; the refusal holds only while the
// history is short of that time, and says whether a computation is getting there.
import { describe, expect, it } from "vitest";
import { BehindRefusals, behindMessage, reachedMessage } from "./behindRefusals";

/** A snapshot source whose horizon and computation the test sets. */
function source(horizon: number, computing: boolean) {
  const listeners = new Set<() => void>();
  let info = { horizon, computing: computing ? {} : null };
  return {
    getSnapshot: () => info,
    subscribe: (l: () => void) => {
      listeners.add(l);
      return () => listeners.delete(l);
    },
    set(h: number, c: boolean) {
      info = { horizon: h, computing: c ? {} : null };
      for (const l of listeners) l();
    },
  };
}

const still = (at: number, now: number) =>
  `The history is still being computed up to t = ${at} s (it reaches ${now} s): edit once it gets there.`;
const cancelled = (at: number, now: number) =>
  `The history reaches only t = ${now} s (its computation was cancelled): go to a computed time, or type t = ${at} s to compute up to it, then edit.`;

describe("behindMessage", () => {
  it("refuses only a time past the horizon, saying whether a computation is getting there", () => {
    expect(behindMessage(5, 5, true)).toBeNull();
    expect(behindMessage(4, 5, false)).toBeNull();
    expect(behindMessage(5, 2.5, true)).toBe(still(5, 2.5));
    expect(behindMessage(5, 2.5, false)).toBe(cancelled(5, 2.5));
    expect(behindMessage(1 / 3 + 5, 1 / 3, true)).toBe(still(5.33333, 0.333333));
    expect(reachedMessage(1 / 3)).toBe(
      "The history has reached t = 0.333333 s: edits there are accepted now.",
    );
  });
});

describe("BehindRefusals", () => {
  it("a refusal lapses once the horizon reaches its time, not before", async () => {
    const s = source(2, true);
    const seen: [string, string | null, number][] = [];
    const r = new BehindRefusals(s, (...args) => seen.push(args));
    const text = r.refuse(5)!;
    expect(text).toBe(still(5, 2));
    let lapsed: string | null | undefined;
    void r.whenChanged(text)!.then((next) => (lapsed = next));
    s.set(4.9, true);
    await null;
    expect(lapsed).toBeUndefined();
    expect(seen).toEqual([]);
    s.set(5, true);
    await null;
    expect(lapsed).toBeNull();
    expect(seen).toEqual([[text, null, 5]]);
    // followed no more
    expect(r.whenChanged(text)).toBeNull();
  });

  it("a computation stopped short changes the refusal to the cancelled one, which lapses in turn", async () => {
    const s = source(2, true);
    const seen: [string, string | null, number][] = [];
    const r = new BehindRefusals(s, (...args) => seen.push(args));
    const text = r.refuse(5)!;
    const changed = r.whenChanged(text)!;
    s.set(3, false);
    const next = await changed;
    expect(next).toBe(cancelled(5, 3));
    expect(seen).toEqual([[text, next, 5]]);
    // typed t = 5: computed again, then there
    const again = r.whenChanged(next!)!;
    s.set(3.5, true);
    const third = await again;
    expect(third).toBe(still(5, 3.5));
    const last = r.whenChanged(third!)!;
    s.set(6, false);
    expect(await last).toBeNull();
  });

  it("no refusal where the history holds the time; other texts are not followed", () => {
    const s = source(10, false);
    const r = new BehindRefusals(s);
    expect(r.refuse(10)).toBeNull();
    expect(r.whenChanged("A r: must be a positive finite number")).toBeNull();
  });
});
