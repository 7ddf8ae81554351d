import { readFileSync } from "node:fs";
import { join } from "node:path";
import { galperin, parseScene, presets, serializeScene } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { buildPreset, DEFAULT_PRESET, PRESETS } from "./presets";

const publicScenes = join(import.meta.dirname, "../../../public/scenes");

describe("presets menu", () => {
  it("lists every engine preset, the default first, Galperin taking digits", () => {
    expect(PRESETS.map((p) => p.id)).toEqual(presets.map((p) => p.id));
    expect(PRESETS[0]?.id).toBe(DEFAULT_PRESET);
    expect(PRESETS.filter((p) => p.takesDigits).map((p) => p.id)).toEqual(["galperin"]);
    expect(buildPreset("galperin", 2)).toEqual(galperin(2));
    expect(() => buildPreset("nope")).toThrow('preset: unknown id "nope"');
  });

  it("the scene files in public/scenes are the engine's presets (regenerate with scripts/generate-preset-files.mjs)", () => {
    const index = JSON.parse(readFileSync(join(publicScenes, "index.json"), "utf8")) as { id: string }[];
    expect(index.length).toBeGreaterThanOrEqual(presets.length);
    for (const p of presets) {
      const text = readFileSync(join(publicScenes, `${p.id}.json`), "utf8");
      expect(text, p.id).toBe(`${serializeScene(p.make())}\n`);
      expect(parseScene(text)).toEqual(parseScene(serializeScene(p.make())));
    }
  });

  it("the titles in public/scenes/index.json say digit for one digit, digits for more", () => {
    const index = JSON.parse(readFileSync(join(publicScenes, "index.json"), "utf8")) as { title: string }[];
    const counts = index.flatMap((e) => [...e.title.matchAll(/\b(\d+) (digits?)\b/g)]);
    expect(counts.length).toBeGreaterThan(1);
    for (const [text, n, word] of counts) expect(word, text).toBe(n === "1" ? "digit" : "digits");
  });
});
