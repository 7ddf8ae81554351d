import { describe, expect, it } from "vitest";
import { META_MAX_DEPTH } from "./meta.js";
import { parseScene } from "./parse.js";
import { serializeScene } from "./serialize.js";

function nested(levels: number): unknown {
  let v: unknown = [];
  for (let i = 1; i < levels; i++) v = [v];
  return v;
}

describe("a scene's meta", () => {
  const head = '{"format":"chapgame","version":1,"actions":[],"meta":';

  it("is refused with a message naming it when nested too deep (10,000 levels overflowed the stack)", () => {
    const deep = `${head}{"x":${"[".repeat(10_000)}${"]".repeat(10_000)}}}`;
    expect(() => parseScene(deep)).toThrow(`meta: must not be nested deeper than ${META_MAX_DEPTH} levels`);
    const scene = {
      format: "chapgame" as const,
      version: 1 as const,
      g: 0,
      gravity: [0, 0] as [number, number],
    };
    expect(() => serializeScene({ ...scene, actions: [], meta: { x: nested(10_000) } })).toThrow(
      "meta: must not be nested deeper",
    );
  });

  it("is kept as it is up to the limit, and must be an object", () => {
    const ok = parseScene(`${head}${JSON.stringify({ x: nested(META_MAX_DEPTH - 1) })}}`);
    expect(JSON.stringify(ok.meta)).toBe(JSON.stringify({ x: nested(META_MAX_DEPTH - 1) }));
    expect(() => parseScene(`${head}${JSON.stringify({ x: nested(META_MAX_DEPTH) })}}`)).toThrow("meta:");
    expect(() => parseScene(`${head}[1]}`)).toThrow("meta: must be an object");
  });
});
