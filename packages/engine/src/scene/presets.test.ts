import { describe, expect, it } from "vitest";
import { parseScene } from "./parse.js";
import {
  billiardsBreak,
  dilutedGas,
  type GasOptions,
  galperin,
  newtonsCradle,
  originalDemo,
  presets,
} from "./presets.js";

describe("presets", () => {
  it("every preset is a valid scene (no overlaps, ids unique)", () => {
    for (const p of presets) expect(() => parseScene(p.make()), p.id).not.toThrow();
    expect(new Set(presets.map((p) => p.id)).size).toBe(presets.length);
  });
  it("originalDemo is the thesis sample", () => {
    const s = originalDemo();
    expect(s.g).toBe(1);
    expect(s.actions).toContainEqual({ time: 0, type: "giveVelocity", id: "B", v: [-100, 0] });
  });
  it("galperin(n) has a big mass of 100^(n-1)", () => {
    expect(galperin(1).actions[2]).toMatchObject({ id: "big", m: 1, v: [-1, 0] });
    expect(galperin(7).actions[2]).toMatchObject({ m: 1e12 });
    expect(() => galperin(0)).toThrow(RangeError);
  });
  it("galperin refuses digits outside 1…9 naming the argument and the value given", () => {
    for (const [digits, got] of [
      [12, "12"],
      [0, "0"],
      [2.5, "2.5"],
      [Number.NaN, "NaN"],
      ["4", 'the string "4"'],
    ] as const)
      expect(() => galperin(digits as number), String(digits)).toThrow(
        new RangeError(`galperin(digits): must be an integer in 1…9 (got ${got})`),
      );
    expect(galperin(9).actions).toHaveLength(3);
  });
  it("newtonsCradle has five touching discs and a striker", () => {
    expect(newtonsCradle().actions).toHaveLength(6);
  });
  it("billiardsBreak racks 15 balls plus the cue ball inside 4 cushions", () => {
    const s = billiardsBreak();
    expect(s.actions.filter((a) => a.type === "addBody")).toHaveLength(16);
    expect(s.actions.filter((a) => a.type === "addLine")).toHaveLength(4);
  });
  it("dilutedGas is deterministic in its seed, and the seed matters", () => {
    const a = dilutedGas({ n: 500, packing: 0.2, seed: 7 });
    expect(dilutedGas({ n: 500, packing: 0.2, seed: 7 })).toEqual(a);
    expect(dilutedGas({ n: 500, packing: 0.2, seed: 8 })).not.toEqual(a);
    expect(() => parseScene(a)).not.toThrow();
    expect(a.actions.filter((x) => x.type === "addBody")).toHaveLength(500);
  });
  it("dilutedGas has the requested packing fraction", () => {
    const s = dilutedGas({ n: 100, packing: 0.1 });
    const right = s.actions.find((a) => a.type === "addLine" && a.id === "right");
    const side = right && right.type === "addLine" ? right.p1[0] : Number.NaN;
    expect((100 * Math.PI) / (side * side)).toBeCloseTo(0.1, 12);
  });
  it("dilutedGas refuses bad options, naming the option and the value given", () => {
    expect(() => dilutedGas({ n: -3, packing: 0.1 })).toThrow(
      new RangeError("dilutedGas(options.n): must be a positive integer (got -3)"),
    );
    expect(() => dilutedGas({ n: 0, packing: 0.1 })).toThrow(
      "dilutedGas(options.n): must be a positive integer (got 0)",
    );
    expect(() => dilutedGas({ n: 10, packing: 0.9 })).toThrow(
      new RangeError("dilutedGas(options.packing): must be a number in (0, 0.5] (got 0.9)"),
    );
    expect(() => dilutedGas({ packing: 0.1 } as GasOptions)).toThrow(
      "dilutedGas(options.n): must be a positive integer (got undefined)",
    );
    // too dense for a grid start: the bound shown is the largest packing that passes, rounded down
    expect(() => dilutedGas({ n: 2, packing: 0.5 })).toThrow(
      new RangeError(
        "dilutedGas(options.packing): must be at most 0.324 for a grid start of 2 discs (got 0.5)",
      ),
    );
    expect(() => dilutedGas({ n: 2, packing: 0.324 })).not.toThrow();
    expect(() => dilutedGas({ n: 2, packing: 0.325 })).toThrow(RangeError);
  });
  // Audit of session 22: the seed went through `>>> 0`, so every fraction (Math.random()), NaN, a
  // string or Infinity gave the scene of seed 0 (1.5 that of 1, -1 that of 4294967295), and a
  // misspelt key (`sed`) the default seed, all without a word.
  it("dilutedGas refuses a seed its generator would change, and an unknown option", () => {
    const opts = (extra: Record<string, unknown>) => ({ n: 10, packing: 0.1, ...extra }) as GasOptions;
    for (const seed of [0.37, 1.5, Number.NaN, Number.POSITIVE_INFINITY, -1, 2 ** 32, "3", null])
      expect(() => dilutedGas(opts({ seed })), String(seed)).toThrow(
        new RangeError(
          `dilutedGas(options.seed): must be a whole number from 0 to 4294967295 (got ${typeof seed === "string" ? 'the string "3"' : String(seed)})`,
        ),
      );
    expect(() => dilutedGas(opts({ sed: 3 }))).toThrow(
      new RangeError("dilutedGas(options.sed): unknown field (known: n, packing, seed)"),
    );
    for (const [options, got] of [
      [undefined, "undefined"],
      [null, "null"],
      [[10, 0.1], "an array of 2"],
      [10, "10"],
    ] as const)
      expect(() => dilutedGas(options as unknown as GasOptions), got).toThrow(
        new RangeError(`dilutedGas(options): must be an object { n, packing, seed } (got ${got})`),
      );
    // the whole range is still taken, and an undefined seed is the default
    expect(dilutedGas(opts({ seed: 0 }))).not.toEqual(dilutedGas(opts({ seed: 2 ** 32 - 1 })));
    expect(dilutedGas(opts({ seed: undefined }))).toEqual(dilutedGas(opts({ seed: 1 })));
  });
  it("parses a 20,000-disc gas quickly enough to be usable (grid overlap check)", () => {
    expect(() => parseScene(dilutedGas({ n: 20_000, packing: 0.3 }))).not.toThrow();
  });
});
