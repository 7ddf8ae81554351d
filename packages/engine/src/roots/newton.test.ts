import { describe, expect, it } from "vitest";
import { RootSolverError, splitPoint } from "./bracket.js";
import { nextUp } from "./exactPoly.js";
import { newtonPlain, pieceRoots, quadRootsPlain } from "./newton.js";

describe("splitPoint", () => {
  it("returns a double strictly inside, or a when a and b are adjacent", () => {
    expect(splitPoint(1, 2)).toBe(1.5);
    expect(splitPoint(1, nextUp(1))).toBe(1);
    expect(splitPoint(-1, 1)).toBe(0);
    const m = splitPoint(0, 1);
    expect(m > 0 && m < 1).toBe(true);
  });
  it("halves in the ordering of doubles: any bracket ends in about 120 halvings", () => {
    const brackets: Array<[number, number]> = [
      [0, 1],
      [-Number.MAX_VALUE, Number.MAX_VALUE],
      [Number.MIN_VALUE, 1e300],
      [-1e-300, -0],
      [-0, 5e-324 * 7],
    ];
    for (const [a0, b0] of brackets) {
      // Always keep the lower half: the slowest direction for value halving near 0.
      const a = a0;
      let b = b0;
      let steps = 0;
      for (;;) {
        const m = splitPoint(a, b);
        if (m === a) break;
        expect(m > a && m < b).toBe(true);
        b = m;
        steps++;
      }
      expect(steps).toBeLessThanOrEqual(130);
    }
  });
});

describe("newtonPlain", () => {
  it("converges to a simple root inside the bracket", () => {
    const c = [-2, 0, 1]; // t² − 2
    const r = newtonPlain(c, 0, 2, 0, 2, -2, 2);
    expect(Math.abs(r - Math.SQRT2)).toBeLessThanOrEqual(4e-16);
  });
  it("ends at a root exactly at 0 of high multiplicity without running into its cap", () => {
    const c = [0, 0, 0, 0, 0, -1e-3, 1]; // t⁵ (t − 1e-3): a 5-fold root at 0
    const r = newtonPlain(c, 0, 6, -1, 5e-4, 2e-3, -1e-18);
    expect(Math.abs(r)).toBeLessThan(1e-300);
  });
  it("reports failure with RootSolverError when its iteration cap is exceeded", () => {
    expect(() => newtonPlain([-2, 0, 1], 0, 2, 0, 2, -2, 2, 0, Number.NaN, 1)).toThrow(RootSolverError);
  });
});

describe("quadRootsPlain", () => {
  it("uses the cancellation-free form: both roots of t² − 1e8 t + 1 to full precision", () => {
    const out = new Float64Array(2);
    const k = quadRootsPlain(1, -1e8, 1, 0, 2e8, out, 0);
    expect(k).toBe(2);
    expect(out[0]).toBeCloseTo(1e-8, 23);
    expect(out[1]).toBeCloseTo(1e8, 6);
  });
  it("keeps the exact root 0 when c0 = 0 even if c1² underflows", () => {
    const out = new Float64Array(2);
    expect(quadRootsPlain(0, 3e-323, 3, -1, 1, out, 0)).toBe(2);
    expect(Array.from(out)).toEqual([-1e-323, 0]);
  });
  it("returns nothing for complex roots", () => {
    const out = new Float64Array(2);
    expect(quadRootsPlain(1, 0, 1, -5, 5, out, 0)).toBe(0);
  });
});

describe("pieceRoots", () => {
  it("finds one root per monotone piece with a sign change", () => {
    // (t − 1)(t − 2)(t − 3): critical points 2 ± 1/√3.
    const c = [-6, 11, -6, 1];
    const splits = new Float64Array([2 - 1 / Math.sqrt(3), 2 + 1 / Math.sqrt(3)]);
    const out = new Float64Array(3);
    const k = pieceRoots(c, 0, 3, 0, 4, splits, 2, out);
    expect(k).toBe(3);
    for (let i = 0; i < 3; i++) expect(Math.abs((out[i] as number) - (i + 1))).toBeLessThan(1e-14);
  });
});
