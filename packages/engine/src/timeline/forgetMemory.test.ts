/**
 * Timeline.forgetBefore returns memory (forget.ts, Records.dropBefore): the records, keyframes and
 * the records' capacity drop, and a game loop that forgets as it goes stays bounded (counts, not
 * timings), reading its kept history as a twin that never forgot.
 */
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { coreOf, disc, expectSameKept } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const BOX: Action[] = [
  { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
  { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 20], kind: "segment" },
  { time: 0, type: "addLine", id: "n", p1: [20, 20], p2: [0, 20], kind: "segment" },
  { time: 0, type: "addLine", id: "w", p1: [0, 20], p2: [0, 0], kind: "segment" },
];

describe("Timeline.forgetBefore: memory", () => {
  it("returns the memory: records, keyframes and capacity drop", () => {
    const gas = dilutedGas({ n: 60, packing: 0.15, seed: 3 });
    const tl = Timeline.fromScene(gas);
    tl.prolong({ events: 20_000 });
    const c = coreOf(tl);
    const before = { records: c.records.length, capacity: c.records.capacity, keyframes: c.keyframes.length };
    const bytes = tl.historyBytes();
    tl.forgetBefore(tl.horizon);
    expect(c.records.length).toBe(before.records - tl.firstEvent);
    expect(c.records.length).toBeLessThan(1024);
    expect(c.keyframes.length).toBe(1);
    expect(before.keyframes).toBeGreaterThan(10);
    expect(c.records.capacity).toBeLessThanOrEqual(2048);
    expect(before.capacity).toBeGreaterThanOrEqual(16_384);
    expect(tl.historyBytes()).toBeLessThan(bytes / 10);
    expect(tl.eventCount).toBe(before.records);
  });

  it("keeps a game loop bounded: an action a frame, forgetBefore(time - 2) each second", () => {
    const tl = new Timeline({ g: 0 });
    const twin = new Timeline({ g: 0 });
    const both = (a: Action) => {
      tl.apply(a);
      twin.apply(a);
    };
    for (const a of BOX) both(a);
    for (let i = 0; i < 12; i++)
      both(disc(`d${i}`, 2 + (i % 4) * 5, 2 + Math.floor(i / 4) * 5, [1 + (i % 3), 2 - (i % 5)]));
    let maxKept = 0;
    let maxKeyframes = 0;
    let maxCapacity = 0;
    for (let frame = 1; frame <= 1000; frame++) {
      const t = frame / 60;
      both({ time: t, type: "giveVelocity", id: `d${frame % 12}`, v: [2 - (frame % 5), 1 + (frame % 3)] });
      tl.prolongTo(t);
      twin.prolongTo(t);
      if (frame % 60 === 0) {
        const start = tl.forgetBefore(Math.max(0, t - 2));
        // the keyframe after the last frame's action at or before t - 2
        if (t >= 2) expect(t - 2 - start).toBeLessThan(1 / 60);
        expect(start).toBeLessThanOrEqual(Math.max(0, t - 2));
      }
      const c = coreOf(tl);
      maxKept = Math.max(maxKept, c.records.length);
      maxKeyframes = Math.max(maxKeyframes, c.keyframes.length);
      maxCapacity = Math.max(maxCapacity, c.records.capacity);
    }
    // 3 s of history at most (2 kept + 1 until the next cut): 180 frames, a keyframe each
    expect(maxKeyframes).toBeLessThanOrEqual(3 * 60 + 2);
    expect(coreOf(twin).keyframes.length).toBeGreaterThan(1000);
    expect(maxKept).toBeLessThan(coreOf(twin).records.length / 4);
    expect(maxCapacity).toBeLessThanOrEqual(coreOf(twin).records.capacity / 2);
    expectSameKept(tl, twin, [tl.historyStart + 0.5, tl.horizon - 0.01]);
  });
});
