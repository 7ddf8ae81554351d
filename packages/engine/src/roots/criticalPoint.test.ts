import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { load } from "./certify.js";
import { movesAwayFromZero, nearestCritical, probeCritical } from "./criticalPoint.js";
import { nextDown, nextUp } from "./exactPoly.js";
import { fcParams, num } from "./testSupport.js";

/**
 * The gap |d|² − R² of a disc passing a point at `off` from the line of its path, d = (off,
 * e + v t + w t²/2): a double root where the path passes the point when off = R (a disc sliding
 * along a channel exactly its diameter wide, past a wall's end point).
 */
function passingGap(off: number, e: number, v: number, w: number, R: number): Float64Array {
  return Float64Array.of(off * off + e * e - R * R, 2 * e * v, v * v + e * w, v * w, 0.25 * w * w);
}

/** Loads the quartic into certify.ts and criticalPoint.ts, as the general solve does (no scaling). */
function loadQuartic(c: Float64Array): void {
  load(c, 4, c, 0);
}

/** nearestCritical and the plain probing search, both ways from x: the same verdicts and bits. */
function expectSameSearch(x: number, lo: number, hi: number): void {
  for (const limit of [lo, hi]) {
    const fast = new Float64Array(2);
    const probed = new Float64Array(2);
    const a = nearestCritical(x, limit, fast);
    const b = probeCritical(x, limit, probed);
    expect(a).toBe(b);
    if (a) expect(Array.from(fast)).toEqual(Array.from(probed));
  }
}

describe("nearestCritical's shortcut (p' moving away from 0)", () => {
  it("is taken on both sides of the double root of a disc sliding past a point on its edge's line", () => {
    // A disc falling at 14,000 along a channel wall, 1.5 before the wall's end (the engine's far
    // window re-expanded about its start): the gap is (1.5 − 14000 t − 4.905 t²)², a perfect square.
    const c = passingGap(-1, 1.5, -14000, -9.81, 1);
    loadQuartic(c);
    const x = 1.5 / 14000;
    const hi = 2.5e-4;
    expect(movesAwayFromZero(nextUp(x), nextDown(hi), 1)).toBe(true);
    expect(movesAwayFromZero(nextUp(0), nextDown(x), 1)).toBe(true);
    expectSameSearch(x, 0, hi);
  });

  it("is refused where p'' changes sign (p = (t² − 1)², p'' = 12 t² − 4) or p''' does", () => {
    loadQuartic(Float64Array.of(1, 0, -2, 0, 1));
    expect(movesAwayFromZero(-2, 2, 1)).toBe(false);
    expect(movesAwayFromZero(0.7, 2, 1)).toBe(true); // p'' > 0 and p''' > 0 beyond 1/√3
    expect(movesAwayFromZero(0.5, 2, 1)).toBe(false); // p''(0.5) = −1 < 0
    expect(movesAwayFromZero(0.7, 2, -1)).toBe(false);
    expect(movesAwayFromZero(-2, -0.7, 1)).toBe(true);
    expect(movesAwayFromZero(-2, 0.7, 1)).toBe(false); // p''' changes sign at 0
    expectSameSearch(1, -2, 2);
    expectSameSearch(0, -2, 2);
  });

  it("gives the probing search's result on passing gaps with and without a double root (property)", () => {
    fc.assert(
      fc.property(
        num(1e-6, 10),
        num(-1e4, 1e4),
        num(-20, 20),
        num(0.1, 10),
        fc.constantFrom(0, 1, -1, 1e-15, -1e-15, 1e-9),
        num(1.01, 4),
        (tStar, v, w, R, rel, span) => {
          // The path passes the point at tStar: e + v tStar + w tStar²/2 = 0 (up to rounding).
          const e = -(v * tStar + 0.5 * w * tStar * tStar);
          const c = passingGap(R * (1 + rel), e, v, w, R);
          if (!c.every(Number.isFinite) || c[4] === 0) return;
          loadQuartic(c);
          expectSameSearch(tStar, 0, span * tStar);
        },
      ),
      fcParams("criticalPoint shortcut", 3000),
    );
  });
});
