import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "../engineTypes";
import { selectionAfterStep } from "./stepSelection";

const a: Action = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
const w: Action = { time: 0, type: "addLine", id: "w", p1: [5, -1], p2: [5, 1], kind: "segment" };
const p: Action = { time: 0, type: "addPoint", id: "p", p: [0, 5] };
const kick: Action = { time: 1, type: "giveVelocity", id: "a", v: [1, 0] };
const scene = (actions: Action[]): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions,
});
const base = [a, w, p];

describe("selectionAfterStep", () => {
  it("the Undo of a Delete selects the body, line or point again; its Redo selects nothing", () => {
    for (const [type, kind, id] of [
      ["removeBody", "body", "a"],
      ["removeLine", "line", "w"],
      ["removePoint", "point", "p"],
    ] as const) {
      const deleted = scene([...base, { time: 2, type, id } as Action]);
      // the scenes come from the worker: equal actions, other objects
      const before = scene(base.map((x) => ({ ...x })));
      expect(selectionAfterStep(deleted, before, null)).toEqual({ kind, id });
      expect(selectionAfterStep(deleted, before, { kind: "body", id: "other" })).toEqual({ kind, id });
      expect(selectionAfterStep(before, deleted, { kind, id })).toBeNull();
    }
  });

  it("keeps the selection through other steps, the Redo of a Delete of another object included", () => {
    const sel = { kind: "line", id: "w" } as const;
    const deletedA = scene([...base, { time: 2, type: "removeBody", id: "a" }]);
    expect(selectionAfterStep(scene(base), deletedA, sel)).toBe(sel);
    // an edit that is no removal, undone and redone
    expect(selectionAfterStep(scene([...base, kick]), scene(base), sel)).toBe(sel);
    expect(selectionAfterStep(scene(base), scene([...base, kick]), sel)).toBe(sel);
    // a step that takes back a removal and more (a rewrite, a loaded scene) selects nothing new
    const both = scene([...base, kick, { time: 2, type: "removeBody", id: "a" }]);
    expect(selectionAfterStep(both, scene(base), sel)).toBe(sel);
    // the same object selected already: the same selection
    const selA = { kind: "body", id: "a" } as const;
    expect(selectionAfterStep(deletedA, scene(base), selA)).toBe(selA);
  });
});
