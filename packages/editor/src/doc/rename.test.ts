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

  it('refuses an id in use by the same kind, and an empty id, in the engine\'s form: `label: must … (got "id")`', () => {
    const refusal = (to: string) => {
      try {
        renameObject(scene, "body", "a", to);
      } catch (e) {
        return (e as Error).message;
      }
      return null;
    };
    expect(refusal("b")).toBe('a id: must not be the id of another body (got "b")');
    expect(refusal("")).toBe('a id: must not be empty (got "")');
    // ids are per kind: the point "a" may take the body "b"'s id
    expect(() => renameObject(scene, "point", "a", "b")).not.toThrow();
  });

  it("quotes the id with JSON escapes, as the engine quotes ids: a quote or a number-like id reads unambiguously", () => {
    const clash = (id: string): SceneFile => ({
      ...scene,
      actions: [...scene.actions, { time: 0, type: "addBody", id, x: 9, y: 9, r: 1, m: 1 }],
    });
    expect(() => renameObject(clash('say "hi"'), "body", "a", 'say "hi"')).toThrow(
      'a id: must not be the id of another body (got "say \\"hi\\"")',
    );
    expect(() => renameObject(clash("12"), "body", "a", "12")).toThrow(
      'a id: must not be the id of another body (got "12")',
    );
  });
});
