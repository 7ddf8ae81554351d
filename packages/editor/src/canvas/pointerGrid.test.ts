// The pointer's precision: places rounded to the coarsest power of ten no larger than a pixel,
// written as their shortest decimal, and moved to another round place only when the rounded one is
// refused and the aim is not.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Vec2 } from "../engineTypes";
import { seedFor } from "../testing/seed";
import { exponentAtMost, FINER_GRIDS, pointerStep, roundToStep, snapPlacement } from "./pointerGrid";

const SEED = seedFor("pointerGrid.test", 20261124);

/** Digits after the decimal point in the shortest decimal of x. */
const decimals = (x: number): number => {
  const [mantissa, exp] = String(x).split("e");
  const frac = mantissa!.split(".")[1]?.length ?? 0;
  return Math.max(0, frac - Number(exp ?? 0));
};

describe("pointerStep", () => {
  it("is the largest power of ten no larger than a pixel in world units", () => {
    expect(pointerStep(1)).toBe(1);
    expect(pointerStep(10)).toBe(0.1);
    expect(pointerStep(3)).toBe(0.1); // a pixel is 0.333 units
    expect(pointerStep(20)).toBe(0.01); // 0.05
    expect(pointerStep(0.37)).toBe(1); // 2.7
    expect(pointerStep(0.05)).toBe(10); // 20
    expect(pointerStep(1e6)).toBe(1e-6);
    expect(pointerStep(1e-6)).toBe(1e6);
    expect(pointerStep(4, 2)).toBe(0.1); // two pixels: 0.5
  });

  it("does not cross a power of ten where log10 rounds (exponentAtMost)", () => {
    for (let e = -12; e <= 12; e++) {
      const p = Number(`1e${e}`);
      expect(exponentAtMost(p)).toBe(e);
      expect(exponentAtMost(p * (1 - 2 ** -52))).toBe(e - 1);
    }
  });
});

describe("roundToStep", () => {
  it("writes the rounded place as its shortest decimal", () => {
    expect(roundToStep(123.45678901234, 0.1)).toBe(123.5);
    expect(String(roundToStep(0.30000000000000004, 0.1))).toBe("0.3");
    expect(String(roundToStep(6.000000000000001, 0.1))).toBe("6");
    expect(roundToStep(-0.04, 0.1)).toBe(0);
    expect(Object.is(roundToStep(-0.04, 0.1), -0)).toBe(false);
    expect(roundToStep(1234.5, 100)).toBe(1200);
    expect(roundToStep(1.26, 0.1, Math.floor)).toBe(1.2);
    expect(roundToStep(1.21, 0.1, Math.ceil)).toBe(1.3);
    // what has no shorter decimal is left alone
    expect(roundToStep(Number.POSITIVE_INFINITY, 1)).toBe(Number.POSITIVE_INFINITY);
    expect(roundToStep(1e20 + 12345, 1e-3)).toBe(1e20 + 12345);
  });

  it("property: within half a step, a multiple of it, with no digit below it", () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e7, max: 1e7, noNaN: true }),
        fc.integer({ min: -7, max: 5 }),
        (x, e) => {
          const step = Number(`1e${e}`);
          const y = roundToStep(x, step);
          expect(Math.abs(y - x)).toBeLessThanOrEqual(step / 2 + Math.abs(x) * 2 ** -50);
          // a multiple of the step: no digit below it (a step of 1 or more: divisible, exactly)
          expect(decimals(y)).toBeLessThanOrEqual(Math.max(0, -e));
          if (e >= 0) expect(Math.abs(y % step)).toBe(0);
        },
      ),
      { seed: SEED, numRuns: 2000 },
    );
  });
});

describe("snapPlacement", () => {
  /** A wall x >= 10 that a disc of radius 1 must keep its centre off (x <= 9 is free). */
  const clearOfWall = (pts: readonly Vec2[]) => pts.every((p) => p[0] <= 9);

  it("takes the rounded place when it fits, and also when the aim itself does not (the engine says why)", () => {
    expect(snapPlacement([[3.14259, 2.71928]], 0.1, clearOfWall)).toEqual([[3.1, 2.7]]);
    expect(snapPlacement([[9.46, 1.04]], 0.1, clearOfWall)).toEqual([[9.5, 1]]);
  });

  it("a rounded place refused next to a free aim goes to the nearest round place that fits, never into the wall", () => {
    const wallAt = (x: number) => (pts: readonly Vec2[]) => pts.every((p) => p[0] <= x);
    // 8.96 fits, its rounded 9.0 does not: the nearest corner of its cell that fits
    expect(snapPlacement([[8.96, 0.33]], 0.1, wallAt(8.965))).toEqual([[8.9, 0.3]]);
    expect(snapPlacement([[8.96, 0.37]], 0.1, wallAt(8.965))).toEqual([[8.9, 0.4]]);
  });

  it("a gap narrower than the step is found on a finer grid; narrower than the finest, the aim itself", () => {
    // free only in 8.961 <= x <= 8.969 (between two walls)
    const slot = (pts: readonly Vec2[]) => pts.every((p) => p[0] >= 8.961 && p[0] <= 8.969);
    expect(snapPlacement([[8.9634, 0]], 0.1, slot)).toEqual([[8.963, 0]]);
    const hair = (pts: readonly Vec2[]) => pts.every((p) => p[0] >= 8.96341 && p[0] <= 8.96342);
    const aim: Vec2 = [8.963415, 5];
    expect(FINER_GRIDS).toBe(2);
    expect(snapPlacement([aim], 0.1, hair)).toEqual([aim]);
  });

  it("a line's two ends move together, the same way on each axis (a level line stays level)", () => {
    // both ends must stay below y = 2.08: the first one's rounded 2.1 is refused, its aim is not
    const below = (pts: readonly Vec2[]) => pts.every((p) => p[1] < 2.08);
    const out = snapPlacement(
      [
        [1.234, 2.06],
        [5.678, 1.51],
      ],
      0.1,
      below,
    );
    // down on both axes strays least (0.079) of the choices that fit (up on x: 0.089)
    expect(out).toEqual([
      [1.2, 2],
      [5.6, 1.5],
    ]);
    // a level line above a disc of radius 1.02 at the origin, 1.04 above it: 1.0 would cross it
    const clear = (pts: readonly Vec2[]) => pts.every((p) => p[1] >= 1.02);
    expect(
      snapPlacement(
        [
          [-5.01, 1.04],
          [5.04, 1.04],
        ],
        0.1,
        clear,
      ),
    ).toEqual([
      [-5, 1.1],
      [5.1, 1.1],
    ]);
  });
});
