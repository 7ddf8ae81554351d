// The name Save file suggests: the file the scene came from, else one made from its title, else
// scene.chapgame.json (Save once always wrote scene.chapgame.json, whatever the scene was).
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { DEFAULT_SAVE_NAME, fileNameFrom, saveNameFor, sceneTitle } from "./saveName";

const scene = (meta?: Record<string, unknown>): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [],
  ...(meta === undefined ? {} : { meta }),
});

describe("saveNameFor", () => {
  it("keeps the name the scene came from as it was, before any title", () => {
    expect(saveNameFor("billiards.chapgame.json", scene({ title: "Other" }))).toBe("billiards.chapgame.json");
    expect(saveNameFor("My Scene (2).json", scene())).toBe("My Scene (2).json");
  });

  it("makes a name from meta.title, else meta.name, when the scene came from no file", () => {
    expect(saveNameFor(null, scene({ title: "My Billiards!" }))).toBe("my-billiards.chapgame.json");
    expect(saveNameFor(null, scene({ name: "Break shot" }))).toBe("break-shot.chapgame.json");
    expect(saveNameFor(null, scene({ title: "  ", name: "Second" }))).toBe("second.chapgame.json");
    expect(saveNameFor("  ", scene({ title: "T" }))).toBe("t.chapgame.json");
  });

  it("falls back to scene.chapgame.json without a name or a usable title", () => {
    expect(DEFAULT_SAVE_NAME).toBe("scene.chapgame.json");
    expect(saveNameFor(null, scene())).toBe(DEFAULT_SAVE_NAME);
    expect(saveNameFor(null, scene({ title: 42, name: ["x"] }))).toBe(DEFAULT_SAVE_NAME);
    expect(saveNameFor(null, scene({ title: "!!! ???" }))).toBe(DEFAULT_SAVE_NAME);
    expect(sceneTitle(scene({ view: { x: 1 } }))).toBeNull();
  });
});

describe("fileNameFrom", () => {
  it("keeps letters and digits of any script, splits camelCase, and joins the rest with hyphens", () => {
    expect(fileNameFrom("billiardsBreak")).toBe("billiards-break.chapgame.json");
    expect(fileNameFrom("Galperin 4 digits")).toBe("galperin-4-digits.chapgame.json");
    expect(fileNameFrom("Café / Ёлка: 3")).toBe("café-ёлка-3.chapgame.json");
    expect(fileNameFrom("../../etc/passwd")).toBe("etc-passwd.chapgame.json");
  });

  it("cuts a long title to 80 characters without a trailing hyphen", () => {
    const name = fileNameFrom(`${"a".repeat(79)} bcd`);
    expect(name).toBe(`${"a".repeat(79)}.chapgame.json`);
  });
});
