import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { renameObject } from "./rename";

const scene: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
    { time: 0, type: "addPoint", id: "a", p: [5, 5] },
    { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
    { time: 1, type: "giveVelocity", id: "a", v: [1, 0] },
  ],
};

describe("renameObject", () => {
  it("renames every action of that object and only of that kind", () => {
    const out = renameObject(scene, "body", "a", "cue");
    expect(out.actions.map((a) => ("id" in a ? a.id : ""))).toEqual(["cue", "a", "b", "cue"]);
  });

  it("refuses an id in use by the same kind, and an empty id", () => {
    expect(() => renameObject(scene, "body", "a", "b")).toThrow('a id: "b" is already used by another body');
    expect(() => renameObject(scene, "body", "a", "")).toThrow("a id: must not be empty");
  });
});
