// Consecutive edits of one object at one instant merge into one action; anything else stays an
// action of its own.
import { describe, expect, it } from "vitest";
import type { Action, SceneState } from "../engineTypes";
import { changesNothing, mergedEdit } from "./mergeEdit";

const addA: Action = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
const addB: Action = { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 };
const xA: Action = { time: 2, type: "updateBody", id: "a", x: 3 };

describe("mergedEdit", () => {
  it("an edit of the object of the action right before it, at the same time, merges into it", () => {
    expect(mergedEdit([addA, xA], { time: 2, type: "updateBody", id: "a", y: 4 })).toEqual({
      index: 1,
      action: { time: 2, type: "updateBody", id: "a", x: 3, y: 4 },
    });
    // a later value of the same field replaces the earlier one
    expect(mergedEdit([addA, xA], { time: 2, type: "updateBody", id: "a", x: 7 })?.action).toEqual({
      time: 2,
      type: "updateBody",
      id: "a",
      x: 7,
    });
    // at the instant it was added: the add changes
    expect(mergedEdit([addA], { time: 0, type: "giveVelocity", id: "a", v: [1, 2] })).toEqual({
      index: 0,
      action: { ...addA, v: [1, 2] },
    });
    expect(mergedEdit([addA], { time: 0, type: "updateBody", id: "a", r: 2, mu: 0.5 })?.action).toEqual({
      ...addA,
      r: 2,
      mu: 0.5,
    });
  });

  it("a velocity given, then a place: an updateBody; a place, then a velocity: the updateBody gains v", () => {
    const kick: Action = { time: 2, type: "giveVelocity", id: "a", v: [1, 0] };
    expect(mergedEdit([addA, kick], { time: 2, type: "updateBody", id: "a", x: 3 })?.action).toEqual({
      time: 2,
      type: "updateBody",
      id: "a",
      v: [1, 0],
      x: 3,
    });
    expect(mergedEdit([addA, kick], { time: 2, type: "giveVelocity", id: "a", v: [0, 1] })?.action).toEqual({
      ...kick,
      v: [0, 1],
    });
    expect(mergedEdit([addA, xA], { time: 2, type: "giveVelocity", id: "a", v: [0, 1] })?.action).toEqual({
      ...xA,
      v: [0, 1],
    });
  });

  it("lines, points and the globals merge the same way", () => {
    const line: Action = { time: 1, type: "addLine", id: "l", p1: [0, 0], p2: [1, 0], kind: "segment" };
    expect(mergedEdit([line], { time: 1, type: "updateLine", id: "l", p2: [2, 0] })?.action).toEqual({
      ...line,
      p2: [2, 0],
    });
    const moved: Action = { time: 3, type: "updateLine", id: "l", kind: "ray" };
    expect(mergedEdit([line, moved], { time: 3, type: "updateLine", id: "l", p1: [1, 1] })?.action).toEqual({
      ...moved,
      p1: [1, 1],
    });
    const point: Action = { time: 0, type: "addPoint", id: "p", p: [0, 0] };
    expect(mergedEdit([point], { time: 0, type: "updatePoint", id: "p", p: [1, 1] })?.action).toEqual({
      ...point,
      p: [1, 1],
    });
    const g: Action = { time: 4, type: "setGlobal", g: 1 };
    expect(mergedEdit([addA, g], { time: 4, type: "setGlobal", gravity: [0, -9.81] })?.action).toEqual({
      ...g,
      gravity: [0, -9.81],
    });
  });

  it("stays an action of its own: another time, another object between, an add or a removal, an until", () => {
    // another time
    expect(mergedEdit([addA, xA], { time: 2.5, type: "updateBody", id: "a", y: 4 })).toBeNull();
    // the action right before its place is another object's (b's add): a's add is not it
    expect(mergedEdit([addA, addB], { time: 0, type: "updateBody", id: "a", x: -3 })).toBeNull();
    const xB: Action = { time: 2, type: "updateBody", id: "b", x: 9 };
    expect(mergedEdit([addA, addB, xA, xB], { time: 2, type: "updateBody", id: "a", y: 4 })).toBeNull();
    // a removal is no field to merge into, and neither adds nor removals merge
    const gone: Action = { time: 2, type: "removeBody", id: "a" };
    expect(mergedEdit([addA, gone], { time: 2, type: "updateBody", id: "a", y: 4 })).toBeNull();
    expect(mergedEdit([addA, xA], { time: 2, type: "removeBody", id: "a" })).toBeNull();
    expect(mergedEdit([addA], { time: 0, type: "addBody", id: "a", x: 1, y: 0, r: 1, m: 1 })).toBeNull();
    // a setGlobal after a body's edit
    expect(mergedEdit([addA, xA], { time: 2, type: "setGlobal", g: 1 })).toBeNull();
    // an edit with an until, or one before every action
    expect(
      mergedEdit([addA, xA], { time: 2, type: "updateBody", id: "a", y: 4, until: { time: 1 } }),
    ).toBeNull();
    expect(mergedEdit([], { time: 0, type: "setGlobal", g: 1 })).toBeNull();
  });

  it("its place is after every action at or before its time: the one before it there is the one it merges into", () => {
    const later: Action = { time: 5, type: "giveVelocity", id: "a", v: [1, 0] };
    expect(mergedEdit([addA, xA, later], { time: 2, type: "updateBody", id: "a", r: 2 })).toEqual({
      index: 1,
      action: { ...xA, r: 2 },
    });
  });
});

describe("changesNothing", () => {
  const state: SceneState = {
    time: 2,
    g: 0.5,
    gravity: [0, -1],
    bodies: [{ id: "a", x: 3, y: 4, vx: 1, vy: -2, ax: 0, ay: -1, r: 1, m: 2, mu: 0 }],
    lines: [{ id: "l", p1: [0, 0], p2: [5, 0], kind: "segment" }],
    points: [{ id: "p", p: [7, 7] }],
  };
  it("an update that sets every field it gives to the value the object has", () => {
    expect(changesNothing({ time: 2, type: "updateBody", id: "a", x: 3, m: 2, v: [1, -2] }, state)).toBe(
      true,
    );
    expect(changesNothing({ time: 2, type: "giveVelocity", id: "a", v: [1, -2] }, state)).toBe(true);
    expect(changesNothing({ time: 2, type: "updateLine", id: "l", p2: [5, 0], kind: "segment" }, state)).toBe(
      true,
    );
    expect(changesNothing({ time: 2, type: "updatePoint", id: "p", p: [7, 7] }, state)).toBe(true);
    expect(changesNothing({ time: 2, type: "setGlobal", g: 0.5, gravity: [0, -1] }, state)).toBe(true);
  });

  it("one value other (even -0 for 0), another object, an add, a removal or an until: something", () => {
    expect(changesNothing({ time: 2, type: "updateBody", id: "a", x: 3, m: 2.5 }, state)).toBe(false);
    expect(changesNothing({ time: 2, type: "giveVelocity", id: "a", v: [1, -2.0000001] }, state)).toBe(false);
    expect(changesNothing({ time: 2, type: "updateLine", id: "l", kind: "line" }, state)).toBe(false);
    expect(changesNothing({ time: 2, type: "setGlobal", gravity: [-0, -1] }, state)).toBe(false);
    expect(changesNothing({ time: 2, type: "updateBody", id: "zz", x: 3 }, state)).toBe(false);
    expect(changesNothing({ time: 2, type: "addBody", id: "a", x: 3, y: 4, r: 1, m: 2 }, state)).toBe(false);
    expect(changesNothing({ time: 2, type: "removeBody", id: "a" }, state)).toBe(false);
    expect(
      changesNothing({ time: 2, type: "giveVelocity", id: "a", v: [1, -2], until: { time: 1 } }, state),
    ).toBe(false);
  });
});
