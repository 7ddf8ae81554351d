import { describe, expect, it } from "vitest";
import { Timeline } from "../timeline/timeline.js";
import { SceneError } from "./errors.js";
import { META_MAX_DEPTH } from "./meta.js";
import { parseScene } from "./parse.js";
import { serializeScene } from "./serialize.js";

function nested(levels: number): unknown {
  let v: unknown = [];
  for (let i = 1; i < levels; i++) v = [v];
  return v;
}

/** A scene without actions, to carry a meta. */
const EMPTY_SCENE = {
  format: "chapgame" as const,
  version: 1 as const,
  g: 0,
  gravity: [0, 0] as [number, number],
  actions: [],
};

describe("a scene's meta", () => {
  const head = '{"format":"chapgame","version":1,"actions":[],"meta":';

  it("is refused with a message naming it when nested too deep (10,000 levels overflowed the stack)", () => {
    const deep = `${head}{"x":${"[".repeat(10_000)}${"]".repeat(10_000)}}}`;
    expect(() => parseScene(deep)).toThrow(`meta: must not be nested deeper than ${META_MAX_DEPTH} levels`);
    expect(() => serializeScene({ ...EMPTY_SCENE, meta: { x: nested(10_000) } })).toThrow(
      "meta: must not be nested deeper",
    );
  });

  it("names where the limit is passed, and a cycle as a cycle (both said only 'must not be nested deeper than 100 levels')", () => {
    const cyclic: Record<string, unknown> = { name: "level" };
    cyclic.self = cyclic;
    expect(() => serializeScene({ ...EMPTY_SCENE, meta: { a: cyclic } })).toThrow(
      /^meta: must not be nested deeper than 100 levels \(got a cycle: meta\.a\.self is meta\.a again, which JSON cannot write\)$/,
    );
    expect(() => Timeline.fromScene({ ...EMPTY_SCENE, meta: cyclic })).toThrow(
      "(got a cycle: meta.self is meta again",
    );
    const deep = `${head}${JSON.stringify({ x: nested(META_MAX_DEPTH) })}}`;
    expect(() => parseScene(deep)).toThrow(/\(got level 101 at meta\.x(\[0\]){18}….*\[0\]\)$/);
  });

  it("is kept as it is up to the limit, and must be an object", () => {
    const ok = parseScene(`${head}${JSON.stringify({ x: nested(META_MAX_DEPTH - 1) })}}`);
    expect(JSON.stringify(ok.meta)).toBe(JSON.stringify({ x: nested(META_MAX_DEPTH - 1) }));
    expect(() => parseScene(`${head}${JSON.stringify({ x: nested(META_MAX_DEPTH) })}}`)).toThrow("meta:");
    expect(() => parseScene(`${head}[1]}`)).toThrow("meta: must be an object");
  });

  it("refuses, naming the path, what JSON cannot carry exactly (audit of session 19: a BigInt threw a raw TypeError, NaN became null, a function vanished, -0 came back 0)", () => {
    const cases: [Record<string, unknown>, string][] = [
      [{ n: 1n }, "meta.n: must be a number, not a BigInt"],
      [{ a: [1, Number.NaN] }, "meta.a[1]: must be a finite number"],
      [{ x: { y: Number.POSITIVE_INFINITY } }, "meta.x.y: must be a finite number"],
      [{ x: Number.NEGATIVE_INFINITY }, "meta.x: must be a finite number"],
      [{ f: () => 1 }, "meta.f: must be JSON data"],
      [{ u: undefined }, "meta.u: must be JSON data"],
      [{ s: Symbol("s") }, "meta.s: must be JSON data"],
      [{ z: -0 }, "meta.z: must not be -0"],
      [{ d: new Date(0) }, "meta.d: must be a plain object or an array"],
      [{ m: new Map([[1, 2]]) }, "meta.m: must be a plain object or an array"],
      // biome-ignore lint/suspicious/noSparseArray: the hole is the case
      [{ h: [1, , 3] }, "meta.h[1]: must not be an empty slot"],
      [{ [Symbol("k")]: 1 }, "meta: must not have symbol keys"],
    ];
    for (const [meta, message] of cases) {
      let err: unknown;
      try {
        serializeScene({ ...EMPTY_SCENE, meta });
      } catch (e) {
        err = e;
      }
      expect(err, message).toBeInstanceOf(SceneError);
      expect((err as Error).message.startsWith(message), `${(err as Error).message}`).toBe(true);
      expect(() => parseScene({ ...EMPTY_SCENE, meta })).toThrow(message);
      expect(() => Timeline.fromScene({ ...EMPTY_SCENE, meta })).toThrow(message);
    }
  });

  it("refuses -0 read from a file as serializeScene does (JSON.stringify would write it back as 0), keeps plain data bit for bit", () => {
    expect(() => parseScene(`${head}{"a":[1,-0]}}`)).toThrow("meta.a[1]: must not be -0");
    expect(() => parseScene(`${head}{"a":-0.0e3}}`)).toThrow("meta.a: must not be -0");
    const meta = {
      s: "x",
      n: 0.1,
      i: -3,
      z: 0,
      b: true,
      nul: null,
      a: [[], {}, [1, { k: "v" }]],
      o: Object.create(null),
    };
    const text = serializeScene({ format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions: [], meta });
    expect(parseScene(text).meta).toEqual(meta);
    expect(Timeline.fromScene(text).toScene().meta).toEqual(meta);
  });
});
