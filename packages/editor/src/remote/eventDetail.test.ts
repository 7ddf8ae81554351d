// findEventDetail: the worker finds the log entry an EventRef names (by time, kind, participants
// and action type) and answers the engine's detail of it, or null when the history has none.
import { newtonsCradle, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { findEventDetail, matches, refOf } from "./eventDetail";

/** Newton's cradle computed 10 s: 6 actions at 0, then 5 collisions at t = 1. */
function cradle() {
  const tl = Timeline.fromScene(newtonsCradle(), { compute: false });
  tl.prolong({ time: 10 });
  return tl;
}

describe("findEventDetail", () => {
  it("finds each of the simultaneous collisions by its participants, with its own before/after", () => {
    const tl = cradle();
    const at = tl.eventsBetween(1, 1);
    expect(at).toHaveLength(5);
    at.forEach((e, k) => {
      const d = findEventDetail(tl, refOf(e));
      expect(d).toEqual(tl.eventDetail(tl.eventIndexAt(1) + k));
      expect(d?.ids).toEqual(e.ids);
    });
  });

  it("finds an action entry by its action type and id", () => {
    const tl = cradle();
    const add = tl.eventsBetween(0, 0).find((e) => e.ids[0] === "c3");
    expect(add).toBeDefined();
    const d = findEventDetail(tl, refOf(add as NonNullable<typeof add>));
    expect(d?.action).toBe("addBody");
    expect(d?.bodies).toEqual([{ id: "c3", before: null, after: expect.objectContaining({ x: 4, vx: 0 }) }]);
    expect(findEventDetail(tl, { time: 0, type: "action", action: "removeBody", ids: ["c3"] })).toBeNull();
  });

  it("null when no entry is at that time or none there matches; a bad time is no entry", () => {
    const tl = cradle();
    expect(findEventDetail(tl, { time: 0.5, type: "bodyBody", ids: ["c1", "c2"] })).toBeNull();
    expect(findEventDetail(tl, { time: 1, type: "bodyBody", ids: ["c1", "c3"] })).toBeNull();
    expect(findEventDetail(tl, { time: 1, type: "stop", ids: ["c1"] })).toBeNull();
    expect(findEventDetail(tl, { time: 99, type: "stop", ids: ["c1"] })).toBeNull();
    expect(findEventDetail(tl, { time: Number.NaN, type: "stop", ids: ["c1"] })).toBeNull();
  });

  it("matches compares time, kind, ids in order and action type", () => {
    const e = { time: 1, type: "bodyBody" as const, ids: ["a", "b"], point: null, normal: null, impulse: 0 };
    expect(matches(e, refOf(e))).toBe(true);
    expect(matches(e, { time: 1, type: "bodyBody", ids: ["b", "a"] })).toBe(false);
    expect(matches(e, { time: 1, type: "bodyBody", ids: ["a"] })).toBe(false);
    expect(matches(e, { time: 1, type: "bodyBody", ids: ["a", "b"], action: "addBody" })).toBe(false);
  });
});
