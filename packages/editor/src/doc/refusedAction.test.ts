import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "../engineTypes";
import { actionFields, entryOf, refusedAction, withActionChanged } from "./refusedAction";

const disc: Action = { time: 1, type: "addBody", id: "b3", x: 0.5, y: 0, r: 1, m: 1, mu: 0, v: [2, 3] };
const doc: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }, disc],
};

describe("refusedAction", () => {
  it("is the action the stop's path names, with the engine's reason and the author's name for it", () => {
    const stopped = 'actions[1]: body "b3" would overlap body "a" at time 1';
    expect(refusedAction({ stopped, stoppedPath: "actions[1]", doc })).toEqual({
      index: 1,
      action: disc,
      path: "actions[1]",
      reason: 'body "b3" would overlap body "a" at time 1',
      name: 'the action at t = 1 s that adds disc "b3"',
    });
  });

  it("is none when nothing stopped, a stop names no action, or its index is not the scene's", () => {
    expect(refusedAction({ stopped: null, stoppedPath: null, doc })).toBeNull();
    expect(refusedAction({ stopped: "a Zeno state", stoppedPath: null, doc })).toBeNull();
    expect(refusedAction({ stopped: "actions[7]: x", stoppedPath: "actions[7]", doc })).toBeNull();
    expect(refusedAction({ stopped: "actions[1]: x", stoppedPath: "actions[1]", doc: null })).toBeNull();
  });
});

describe("actionFields", () => {
  it("lists the time, then each number, a vector's components by the tables' names", () => {
    const fields = actionFields(disc);
    expect(fields.map((f) => [f.name, f.value])).toEqual([
      ["t", 1],
      ["x", 0.5],
      ["y", 0],
      ["r", 1],
      ["m", 1],
      ["μ", 0],
      ["vx", 2],
      ["vy", 3],
    ]);
    expect(fields.find((f) => f.name === "vy")?.set(9)).toEqual({ ...disc, v: [2, 9] });
    expect(fields.find((f) => f.name === "t")?.set(2)).toEqual({ ...disc, time: 2 });
    expect(disc).toMatchObject({ v: [2, 3], time: 1 }); // the action itself is left as it was
  });

  it("names a line's ends and the globals as their cells do", () => {
    const line: Action = { time: 0, type: "addLine", id: "L", p1: [0, 1], p2: [2, 3], kind: "segment" };
    expect(actionFields(line).map((f) => f.name)).toEqual(["t", "x1", "y1", "x2", "y2"]);
    const globals: Action = { time: 2, type: "setGlobal", g: 1, gravity: [0, -1] };
    expect(actionFields(globals).map((f) => f.name)).toEqual(["t", "g", "gravity x", "gravity y"]);
  });
});

describe("withActionChanged", () => {
  it("replaces the action, kept in applying order, and refuses when the scene no longer holds it there", () => {
    const moved = { ...disc, time: 0 } as Action;
    const to = withActionChanged(doc, 1, entryOf(disc), moved);
    expect(to.actions).toEqual([doc.actions[0], moved]);
    const early = { ...disc, time: -1 } as Action;
    expect(withActionChanged(doc, 1, entryOf(disc), early).actions).toEqual([early, doc.actions[0]]);
    expect(() => withActionChanged(doc, 0, entryOf(disc), moved)).toThrow(/The scene changed since/);
  });
});
