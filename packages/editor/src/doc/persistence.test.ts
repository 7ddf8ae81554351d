import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { decodeSceneFromUrl, encodeSceneForUrl, sceneFromHash } from "./persistence";

const scene: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "ä/β", x: 1, y: 2, r: 3, m: 4, mu: 0.5, v: [1, -1] }],
};

describe("persistence", () => {
  it("a scene survives the URL round trip, also with non-ASCII ids, and the code is URL-safe", () => {
    const code = encodeSceneForUrl(scene);
    expect(code).toMatch(/^[A-Za-z0-9_-]+$/);
    expect(decodeSceneFromUrl(code)).toEqual(scene);
    expect(sceneFromHash(`#scene=${code}`)).toEqual(scene);
    expect(sceneFromHash("#other")).toBeNull();
  });

  it("a damaged link code is refused with a plain message; a scene error still names the field", () => {
    for (const code of ["abc%%", "@@@@", encodeSceneForUrl(scene).slice(0, 40)])
      expect(() => decodeSceneFromUrl(code)).toThrow(/^the scene code after #scene= is damaged|^json: /);
    expect(() => decodeSceneFromUrl("abc%%")).toThrow("damaged or cut short");
    const bad = encodeSceneForUrl({ ...scene, actions: [{ ...scene.actions[0]!, r: -1 } as never] });
    expect(() => decodeSceneFromUrl(bad)).toThrow("actions[0].r");
  });
});
