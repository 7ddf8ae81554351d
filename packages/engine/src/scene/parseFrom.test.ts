// parseSceneFrom(read): parseScene of the text read() gives, the same scene and the same refusals.
import { describe, expect, it } from "vitest";
import { parseScene, parseSceneFrom } from "./parse.js";

const scene = (actions: string) => `{"format": "chapgame", "version": 1, "actions": [${actions}]}`;
const disc = (id: string, x: number | string, extra = "") =>
  `{"time": 0, "type": "addBody", "id": "${id}", "x": ${x}, "y": 0, "r": 1, "m": 1${extra}}`;

/** The scene, or the refusal's message. */
function outcome(parse: () => unknown): unknown {
  try {
    return parse();
  } catch (e) {
    return `${(e as Error).name}: ${(e as Error).message}`;
  }
}

describe("parseSceneFrom", () => {
  it("gives what parseScene gives, scene or refusal", () => {
    const texts = [
      scene(`${disc("a", 0)}, ${disc("b", 5, ', "v": [1, 0]')}`),
      `\uFEFF${scene(disc("a", 0))}`, // a byte order mark
      scene(`${disc("a", 0)}, ${disc("b", 1)}`), // an overlap
      scene(disc("a", 0, ', "r": 2')), // a duplicate key
      scene(disc("a", 0, ', "mu": 1e-999')), // a literal that reads as 0 (allowed for mu)
      scene(`{"time": 0, "type": "addBody", "id": "a", "x": 0, "y": 0, "r": 1e-999, "m": 1}`),
      scene(disc("a", "1e999")), // a literal beyond the largest double
      '{"format": "chapgame", "version": 1,',
      "[]",
    ];
    for (const text of texts)
      expect(
        outcome(() => parseSceneFrom(() => text)),
        text,
      ).toEqual(outcome(() => parseScene(text)));
    expect(outcome(() => parseSceneFrom(() => texts[2] as string))).toMatch(/would overlap/);
  });
});
