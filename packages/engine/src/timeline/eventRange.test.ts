import { describe, expect, it } from "vitest";
import { dilutedGas, galperin } from "../scene/presets.js";
import { Timeline } from "./timeline.js";

describe("Timeline.eventRange", () => {
  it("gives the log by index in pieces that join to the whole log (across keyframes)", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 40, packing: 0.2, seed: 3 }));
    tl.prolong({ events: 5000 });
    const all = tl.eventsBetween(0, tl.horizon);
    expect(all).toHaveLength(tl.eventCount);
    const pieces = [];
    for (let i = 0; i < tl.eventCount; i += 777) pieces.push(...tl.eventRange(i, i + 777));
    expect(pieces).toEqual(all);
    expect(tl.eventRange(3, 4)).toEqual([tl.event(3)]);
  });

  it("clamps the end to eventCount, gives [] for an empty range, refuses indices that are not integers", () => {
    const tl = Timeline.fromScene(galperin(2));
    tl.prolong({});
    const n = tl.eventCount;
    expect(tl.eventRange(n - 2, n + 100)).toEqual([tl.event(n - 2), tl.event(n - 1)]);
    expect(tl.eventRange(5, 5)).toEqual([]);
    expect(tl.eventRange(n + 3, n + 9)).toEqual([]);
    expect(() => tl.eventRange(-1, 3)).toThrow("eventRange(start): must be an integer >= 0 (got -1)");
    expect(() => tl.eventRange(0, 1.5)).toThrow(
      "eventRange(end): must be an integer >= 0 or Infinity (got 1.5)",
    );
    expect(() => tl.eventRange(Number.NaN, 2)).toThrow(RangeError);
  });
});
