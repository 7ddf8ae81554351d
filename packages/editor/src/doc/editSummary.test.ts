import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "../engineTypes";
import { summarizeEdit } from "./editSummary";

const a: Action = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
const kick: Action = { time: 4.25, type: "giveVelocity", id: "a", v: [1, 0] };
const scene = (actions: Action[], g = 9.81): SceneFile => ({
  format: "chapgame",
  version: 1,
  g,
  gravity: [0, 0],
  actions,
});

describe("summarizeEdit", () => {
  it("names one added or removed action with its time, comparing actions by content", () => {
    expect(summarizeEdit(scene([a]), scene([{ ...a }, kick]))).toBe('give velocity to "a" at t = 4.25 s');
    expect(summarizeEdit(scene([a, kick]), scene([{ ...a }]))).toBe(
      'the removal of give velocity to "a" at t = 4.25 s',
    );
  });

  it("counts repeated identical actions, names a rename, and sums up other changes by their earliest time", () => {
    expect(summarizeEdit(scene([a, kick]), scene([a, kick, { ...kick }]))).toBe(
      'give velocity to "a" at t = 4.25 s',
    );
    const renamed = [
      { ...a, id: "b" },
      { ...kick, id: "b" },
    ];
    expect(summarizeEdit(scene([a, kick]), scene(renamed))).toBe('the rename of "a" to "b"');
    const moved = [
      { ...a, id: "b", x: 5 },
      { ...kick, id: "b" },
    ];
    expect(summarizeEdit(scene([a, kick]), scene(moved))).toBe(
      "a change of 4 actions, the earliest at t = 0 s",
    );
  });

  it("an edit merged into the action before it is said as the fields it changed in that action", () => {
    const x: Action = { time: 2, type: "updateBody", id: "a", x: 3 };
    expect(summarizeEdit(scene([a, x]), scene([a, { ...x, y: 4, r: 2 }]))).toBe(
      'the change of y, r in update body "a" at t = 2 s',
    );
    expect(summarizeEdit(scene([a]), scene([{ ...a, x: 5 }]))).toBe(
      'the change of x in add body "a" at t = 0 s',
    );
    // a velocity given, then a place: the giveVelocity became an updateBody
    expect(summarizeEdit(scene([a, kick]), scene([a, { ...kick, type: "updateBody", x: 1 }]))).toBe(
      'the change of x in update body "a" at t = 4.25 s',
    );
    // another object's action, or another time, is no such change
    expect(summarizeEdit(scene([a, x]), scene([a, { ...x, id: "b" }]))).toBe('the rename of "a" to "b"');
    expect(summarizeEdit(scene([a, x]), scene([a, { ...x, time: 3 }]))).toBe(
      "a change of 2 actions, the earliest at t = 2 s",
    );
  });

  it("says when only the globals changed, or nothing did", () => {
    expect(summarizeEdit(scene([a]), scene([a], 1))).toBe("a change of the scene's g or gravity");
    expect(summarizeEdit(scene([a]), scene([a]))).toBe("a change that left the actions as they were");
  });
});
