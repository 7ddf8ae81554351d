// findEventDetail: the worker finds the log entry an EventRef names (by time, kind, participants
// and action type) and answers the engine's detail of it, or null when the history has none;
// stepEventDetail walks the log entry by entry, also through entries alike at one instant.
import { newtonsCradle, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { findEventDetail, matches, refKey, refOf, stepEventDetail } from "./eventDetail";
import type { EventRef } from "./protocol";

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
      const i = tl.eventIndexAt(1) + k;
      // with whether it is the log's first or last entry (Event details greys out its steps there)
      expect(d).toEqual({ ...tl.eventDetail(i), first: false, last: i === tl.eventCount - 1 });
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
    const e = {
      time: 1,
      type: "bodyBody" as const,
      ids: ["a", "b"] as [string, string],
      point: [0, 0] as const,
      normal: [1, 0] as const,
      impulse: 0,
    };
    expect(matches(e, refOf(e))).toBe(true);
    expect(matches(e, { time: 1, type: "bodyBody", ids: ["b", "a"] })).toBe(false);
    expect(matches(e, { time: 1, type: "bodyBody", ids: ["a"] })).toBe(false);
    expect(matches(e, { time: 1, type: "bodyBody", ids: ["a", "b"], action: "addBody" })).toBe(false);
  });
});

/** Every entry's ref reached by stepping from `start` by `step` until the end of the log. */
function walk(tl: Timeline, start: EventRef, step: 1 | -1): EventRef[] {
  const refs: EventRef[] = [];
  for (let at = stepEventDetail(tl, start, step); at !== null; at = stepEventDetail(tl, at.ref, step)) {
    expect(findEventDetail(tl, at.ref)).toEqual(at.detail);
    refs.push(at.ref);
  }
  return refs;
}

describe("stepEventDetail", () => {
  it("walks the cradle's log entry by entry both ways, the five collisions at t = 1 one by one", () => {
    const tl = cradle();
    const n = tl.eventCount;
    const first = refOf(tl.event(0));
    const forward = walk(tl, first, 1);
    expect(forward).toHaveLength(n - 1);
    for (const [k, ref] of forward.entries()) expect(matches(tl.event(k + 1), ref)).toBe(true);
    expect(forward.filter((r) => r.time === 1 && r.type === "bodyBody")).toHaveLength(5);
    const last = forward[forward.length - 1]!;
    expect(walk(tl, last, -1).map(refKey)).toEqual([first, ...forward.slice(0, -1)].reverse().map(refKey));
  });

  it("tells entries alike apart by nth, so stepping does not come back to the first of them", () => {
    const scene: SceneFile = {
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, 0],
      actions: [
        { time: 0, type: "addBody", id: "b", x: 0, y: 0, r: 1, m: 1 },
        { time: 1, type: "updateBody", id: "b", x: 5 },
        { time: 1, type: "updateBody", id: "b", y: 5 },
        { time: 1, type: "updateBody", id: "b", x: 7 },
      ],
    };
    const tl = Timeline.fromScene(scene, { compute: false });
    tl.prolong({ time: 2 });
    const refs = walk(tl, refOf(tl.event(0)), 1);
    expect(refs.map((r) => [r.time, r.action, r.nth])).toEqual([
      [1, "updateBody", undefined],
      [1, "updateBody", 1],
      [1, "updateBody", 2],
    ]);
    expect(new Set(refs.map(refKey)).size).toBe(3);
    expect(stepEventDetail(tl, refs[2]!, -1)?.ref).toEqual(refs[1]);
  });

  it("null at both ends of the log and for an entry the history does not hold", () => {
    const tl = cradle();
    expect(stepEventDetail(tl, refOf(tl.event(0)), -1)).toBeNull();
    expect(stepEventDetail(tl, refOf(tl.event(tl.eventCount - 1)), 1)).toBeNull();
    expect(stepEventDetail(tl, { time: 1, type: "bodyBody", ids: ["c1", "c3"] }, 1)).toBeNull();
    expect(stepEventDetail(tl, { time: 1, type: "bodyBody", ids: ["c1", "c2"], nth: 1 }, 1)).toBeNull();
  });
});
