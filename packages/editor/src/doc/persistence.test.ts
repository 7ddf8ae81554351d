// @vitest-environment jsdom
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import {
  AUTOSAVE_KEY,
  decodeSceneFromUrl,
  encodeSceneForUrl,
  loadAutosave,
  saveAutosave,
  sceneFromHash,
} from "./persistence";

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

  it("autosave round-trips through localStorage and ignores broken entries", () => {
    saveAutosave(localStorage, scene);
    expect(loadAutosave(localStorage)).toEqual(scene);
    localStorage.setItem("chapgame.editor.autosave.v1", "{broken");
    expect(loadAutosave(localStorage)).toBeNull();
  });

  it("a damaged link code is refused with a plain message; a scene error still names the field", () => {
    for (const code of ["abc%%", "@@@@", encodeSceneForUrl(scene).slice(0, 40)])
      expect(() => decodeSceneFromUrl(code)).toThrow(/^the scene code after #scene= is damaged|^json: /);
    expect(() => decodeSceneFromUrl("abc%%")).toThrow("damaged or cut short");
    const bad = encodeSceneForUrl({ ...scene, actions: [{ ...scene.actions[0]!, r: -1 } as never] });
    expect(() => decodeSceneFromUrl(bad)).toThrow("actions[0].r");
  });

  it("a scene too large for the storage leaves no older autosave behind and says so", () => {
    saveAutosave(localStorage, scene);
    const full: Storage = {
      ...localStorage,
      length: 1,
      key: () => AUTOSAVE_KEY,
      clear: () => localStorage.clear(),
      getItem: (k) => localStorage.getItem(k),
      removeItem: (k) => localStorage.removeItem(k),
      setItem: () => {
        throw new DOMException("quota", "QuotaExceededError");
      },
    };
    const bigger = { ...scene, g: 1 };
    expect(saveAutosave(full, bigger)).toMatch(/^Autosave failed/);
    // a reload must not bring back the older scene as if it were the latest
    expect(loadAutosave(localStorage)).toBeNull();
    expect(saveAutosave(localStorage, bigger)).toBeNull();
    expect(loadAutosave(localStorage)).toEqual(bigger);
  });
});
