import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import {
  decodeSceneFromUrl,
  encodeSceneForUrl,
  MAX_SHARE_URL_CHARS,
  sceneFromHash,
  shareLinkProblem,
  shareUrl,
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

  it("infinite masses survive the link (plain JSON would write them as null and the link be refused)", () => {
    const wall: SceneFile = {
      ...scene,
      actions: [{ time: 0, type: "addBody", id: "w", x: 0, y: 0, r: 1, m: Number.POSITIVE_INFINITY }],
    };
    const back = decodeSceneFromUrl(encodeSceneForUrl(wall));
    expect(back.actions).toHaveLength(1);
    expect(back.actions[0]).toMatchObject({ id: "w", m: Number.POSITIVE_INFINITY });
  });

  it("a damaged link code is refused with a plain message; a scene error still names the field", () => {
    for (const code of ["abc%%", "@@@@", encodeSceneForUrl(scene).slice(0, 40)])
      expect(() => decodeSceneFromUrl(code)).toThrow(/^the scene code after #scene= is damaged|^json: /);
    expect(() => decodeSceneFromUrl("abc%%")).toThrow("damaged or cut short");
    // encodeSceneForUrl refuses such a scene itself: a link made elsewhere
    const text = JSON.stringify({ ...scene, actions: [{ ...scene.actions[0]!, id: "a", r: -1 }] });
    const bad = btoa(text).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
    expect(() => encodeSceneForUrl(JSON.parse(text))).toThrow("actions[0].r");
    // the action named as the author knows it, the engine's path kept in parentheses
    expect(() => decodeSceneFromUrl(bad)).toThrow(
      'the action at t = 0 s that adds disc "a" (actions[0].r): ',
    );
  });
});

describe("share links", () => {
  it("refuses a link longer than browsers open, saying its size and what to do instead (20,000 discs gave a 3.2 MB link that failed to open)", () => {
    const discs = Array.from({ length: 20_000 }, (_, i) => ({
      time: 0,
      type: "addBody" as const,
      id: `d${i}`,
      x: 3 * (i % 200),
      y: 3 * Math.floor(i / 200),
      r: 1,
      m: 1,
      v: [1.234567, -0.7654321] as [number, number],
    }));
    const big: SceneFile = { format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions: discs };
    const url = shareUrl({ origin: "http://127.0.0.1:5173", pathname: "/" }, big);
    expect(url.length).toBeGreaterThan(MAX_SHARE_URL_CHARS);
    expect(shareLinkProblem(url)).toMatch(
      /^This scene's link would be \d+\.\d MB, longer than browsers open \(about 2 MB\): use Save/,
    );
    const small = shareUrl(
      { origin: "http://127.0.0.1:5173", pathname: "/" },
      { ...big, actions: discs.slice(0, 10) },
    );
    expect(shareLinkProblem(small)).toBeNull();
  });
});
