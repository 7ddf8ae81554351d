import { describe, expect, it } from "vitest";
import { RootSolverError } from "./bracket.js";
import { exactDerivativeSign, exactPolySign, nextDown, nextUp, ulpsToExactRoot } from "./exactPoly.js";
import { evalPoly, realRoots } from "./realRoots.js";
import { expectVerified, fromRoots } from "./testSupport.js";

/** Every root within 4 ulps of an exact root, sorted, inside, and no exact sign change missed. */
function expectCertified(c: readonly number[], lo: number, hi: number, samples = 64): number[] {
  const roots = realRoots(c, lo, hi);
  expectVerified(c, lo, hi, roots, samples);
  return roots;
}

describe("realRoots: each degree", () => {
  it("linear: the correctly rounded root, inside the interval only", () => {
    expect(realRoots([1, -2], 0, 10)).toEqual([0.5]);
    expect(realRoots([-1, 3], 0, 1)).toEqual([1 / 3]);
    expect(realRoots([1, -2], 0.6, 10)).toEqual([]);
  });
  it("quadratic: both roots, no cancellation for tiny products (stable form)", () => {
    expect(realRoots([2, -3, 1], -10, 10)).toEqual([1, 2]);
    // t² − 1e8 t + 1 : roots ≈ 1e-8 and 1e8; the naive formula loses the small one entirely.
    const r = expectCertified([1, -1e8, 1], 0, 2e8);
    expect(r.length).toBe(2);
    expect(r[0]).toBeCloseTo(1e-8, 22);
  });
  it("cubic with three roots and a cubic with one", () => {
    expect(realRoots([-6, 11, -6, 1], 0, 10)).toEqual([1, 2, 3]);
    expectCertified([1, 1, 0, 1], -5, 5);
  });
  it("quartic with four exact roots", () => {
    expect(realRoots([24, -50, 35, -10, 1], 0, 10)).toEqual([1, 2, 3, 4]);
  });
  it("degree 10 (Wilkinson-like, exact integer coefficients): every root exactly", () => {
    const ks = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10];
    expect(realRoots(fromRoots(ks), 0, 11)).toEqual(ks);
  });
  it("no roots: positive definite quartic and a quadratic with complex roots", () => {
    expect(realRoots([1, 0, 0, 0, 1], -100, 100)).toEqual([]);
    expect(realRoots([1, 0, 1], -5, 5)).toEqual([]);
    expect(realRoots([5, 1, 2, 3, 4], 0, 10)).toEqual([]);
  });
  it("constant and zero polynomials have no isolated roots", () => {
    expect(realRoots([], 0, 1)).toEqual([]);
    expect(realRoots([3], 0, 1)).toEqual([]);
    expect(realRoots([0, 0, 0], 0, 1)).toEqual([]);
  });
});

describe("realRoots: interval ends", () => {
  it("finds roots exactly at lo and at hi", () => {
    expect(realRoots([2, -3, 1], 1, 2)).toEqual([1, 2]);
    expect(realRoots([-6, 11, -6, 1], 1, 3)).toEqual([1, 2, 3]);
    expect(realRoots([0, 1, 1], 0, 5)).toEqual([0]);
  });
  it("does not report a root one ulp outside the interval", () => {
    expect(realRoots([-3, 1], nextUp(3), 4)).toEqual([]);
    expect(realRoots([-3, 1], 2, nextDown(3))).toEqual([]);
  });
  it("a point interval holds a root only where p is exactly 0", () => {
    expect(realRoots([-3, 1], 3, 3)).toEqual([3]);
    expect(realRoots([-1, 0.1], 10, 10)).toEqual([]); // 10·0.1 − 1 ≠ 0 exactly
  });
  it("infinite ends are clamped to Cauchy's root bound", () => {
    expect(realRoots([-6, 11, -6, 1], Number.NEGATIVE_INFINITY, Number.POSITIVE_INFINITY)).toEqual([1, 2, 3]);
    expect(realRoots([-1, 0, 1], 0, Number.POSITIVE_INFINITY)).toEqual([1]);
    expect(realRoots([1, 0, 1], Number.NEGATIVE_INFINITY, Number.POSITIVE_INFINITY)).toEqual([]);
  });
  it("an empty interval (lo > hi) has no roots", () => {
    expect(realRoots([-3, 1], 4, 2)).toEqual([]);
  });
});

describe("realRoots: multiple roots", () => {
  it("an exact double root (a grazing contact) is found exactly", () => {
    expect(realRoots(fromRoots([1, 1, 3]), 0, 5)).toEqual([1, 3]);
    expect(realRoots([1, -2, 1], -5, 5)).toEqual([1]);
  });
  it("exact triple and quadruple roots are found exactly", () => {
    expect(realRoots(fromRoots([2, 2, 2]), 0, 5)).toEqual([2]);
    expect(realRoots(fromRoots([0.5, 0.5, 0.5, 0.5]), -3, 3)).toEqual([0.5]);
    expect(realRoots(fromRoots([-1, -1, 2, 2]), -3, 3)).toEqual([-1, 2]);
  });
  it("a rounded double root whose exact polynomial has two close roots gives both, certified", () => {
    // (t − 0.1)²: the rounded coefficients have two real roots about 1e-9 either side of 0.1.
    const r = expectCertified([0.01, -0.2, 1], 0, 1);
    expect(r.length).toBe(2);
  });
  it("LIMIT: a grazing root whose rounded coefficients miss zero is reported, but cannot be within 4 ulps", () => {
    // With c0 one ulp above 0.01 the exact polynomial t² − 0.2t + c0 is positive everywhere (its
    // minimum is about +3e-18), yet it is within rounding (plain evaluation error bound) of a double
    // root at 0.1: a grazing contact. It is reported as the exact critical point; no exact root exists
    // at all, so the 4-ulp guarantee cannot apply (see README: accuracy limits).
    const c = [nextUp(0.01), -0.2, 1];
    const r = realRoots(c, 0, 1);
    expect(r.length).toBe(1);
    const x = r[0] as number;
    expect(ulpsToExactRoot(c, x)).toBe(Number.POSITIVE_INFINITY);
    // It is the critical point: p' changes sign within one ulp.
    const s = exactDerivativeSign(c, x);
    expect(
      s === 0 || exactDerivativeSign(c, nextUp(x)) !== s || exactDerivativeSign(c, nextDown(x)) !== s,
    ).toBe(true);
    expect(exactPolySign(c, x)).toBe(1);
  });
});

describe("realRoots: degree drop and scale", () => {
  it("drops a leading coefficient negligible over the interval, still certified on the full polynomial", () => {
    const r = expectCertified([-1, 1, 1e-30], 0, 10);
    expect(r).toEqual([1]);
    // The same coefficient is not negligible over a huge interval: its far root -1e30 is found.
    const far = realRoots([-1, 1, 1e-30], -2e30, 10);
    expect(far.length).toBe(2);
    expect((far[0] as number) / -1e30).toBeCloseTo(1, 12);
  });
  it("degenerate leading zeros are trimmed", () => {
    expect(realRoots([2, -3, 1, 0, 0], -10, 10)).toEqual([1, 2]);
    expect(realRoots([1, -1, 0, 0], -10, 10)).toEqual([1]);
  });
  it("coefficients scaled by 1e-300 and by 1e300 give the same roots", () => {
    const base = fromRoots([0.25, 1.5, 3, 7]);
    const r0 = realRoots(base, 0, 10);
    expect(r0).toEqual([0.25, 1.5, 3, 7]);
    for (const s of [1e-300, 1e300, 2 ** -1000, 2 ** 1000]) {
      const c = base.map((x) => x * s);
      const r = expectCertified(c, 0, 10);
      expect(r.length).toBe(4);
      for (let i = 0; i < 4; i++) expect(r[i]).toBeCloseTo(r0[i] as number, 12);
    }
  });
  it("tiny and huge roots: roots and interval scaled by 1e-100 and 1e100 (variable scaling)", () => {
    for (const s of [1e-100, 1e100]) {
      const r = expectCertified(fromRoots([1 * s, 2 * s, 3 * s]), 0, 4 * s);
      expect(r.length).toBe(3);
      for (let i = 0; i < 3; i++) expect((r[i] as number) / s).toBeCloseTo(i + 1, 12);
    }
  });
  it("roots near 1e-200 whose values underflow: only the exact root 0 of the underflowed product", () => {
    // fromRoots([1e-200, 2e-200, 3e-200]) underflows to t³ − 6e-200 t²: roots 0 (double) and 6e-200.
    const c = fromRoots([1e-200, 2e-200, 3e-200]);
    expect(c).toEqual([0, 0, -6e-200, 1]);
    expect(realRoots(c, 0, 4e-200)).toEqual([0]);
    expect(realRoots(c, -1e-199, 1e-199)).toEqual([0, 6e-200]);
  });
});

describe("realRoots: hard published cases", () => {
  it("clustered roots representable exactly: 1, 1+2^-12, 1+2^-11, 1+3·2^-12 (exact coefficients)", () => {
    const ks = [1, 1 + 2 ** -12, 1 + 2 ** -11, 1 + 3 * 2 ** -12];
    const c = fromRoots(ks);
    for (let i = 0; i < ks.length; i++) expect(exactPolySign(c, ks[i] as number)).toBe(0);
    expect(realRoots(c, 0, 2)).toEqual(ks);
  });
  it("LIMIT: the cluster (t−1)(t−1−1e−8)(t−1−2e−8)(t−1−3e−8) with rounded coefficients", () => {
    // Rounding the coefficients (relative 1e-16) perturbs p near 1 by ~1e-15, while the cluster
    // itself only reaches |p| ~ 1e-32: the exact polynomial of the rounded coefficients no longer has
    // roots at 1 + k·1e-8 (a 4-fold cluster moves by ~(1e-15)^(1/4) ≈ 1e-4). No solver can recover
    // the intended roots from these doubles; what is asserted is the guarantee for the polynomial
    // that was given: every root within 4 ulps of an exact root, no exact sign change missed.
    const c = fromRoots([1, 1 + 1e-8, 1 + 2e-8, 1 + 3e-8]);
    const r = expectCertified(c, 0.99, 1.01, 200);
    for (const x of r) expect(Math.abs(x - 1)).toBeLessThan(1e-3);
  });
  it("roots spread over 13 orders of magnitude: 1e-8, 1e-3, 1, 1e5", () => {
    const ks = [1e-8, 1e-3, 1, 1e5];
    const r = expectCertified(fromRoots(ks), 0, 2e5, 200);
    expect(r.length).toBe(4);
    for (let i = 0; i < 4; i++) expect((r[i] as number) / (ks[i] as number)).toBeCloseTo(1, 9);
  });
  it("near-double roots 1 and 1 + 1e-7 next to a far root", () => {
    const r = expectCertified(fromRoots([-2, 1, 1 + 1e-7]), -3, 3, 100);
    expect(r.length).toBe(3);
    // Conditioning, not solver error: rounding the coefficients (~1e-16) moves roots 1e-7 apart by
    // ~1e-16/|p'| ≈ 1e-9; the solver's answer is within 4 ulps of the exact roots of those doubles.
    expect(r[1] as number).toBeCloseTo(1, 8);
    expect(r[2] as number).toBeCloseTo(1 + 1e-7, 8);
  });
  it("Wilkinson's polynomial of degree 20 (rounded coefficients): certified, no sign change missed", () => {
    const ks = Array.from({ length: 20 }, (_, i) => i + 1);
    const c = fromRoots(ks);
    const r = expectCertified(c, 0, 21, 84);
    // The roots found lie where Wilkinson's roots are, up to the (famous) conditioning: rounding the
    // coefficients moves root k by up to ~1e-9·k^k-ish; the first ones stay within 1e-6.
    expect(r.length).toBeGreaterThanOrEqual(10);
    for (let i = 0; i < 5; i++) expect(r[i]).toBeCloseTo(i + 1, 6);
  });
  it("a collision quartic with a grazing-free double crossing: |d + u t|² − R² with a near miss", () => {
    // d = (0, 1.0000001), u = (1, 0): the distance stays above 1 by 1e-7: no root; with 0.9999999, two.
    const miss = realRoots([1.0000001 ** 2 - 1, 0, 1], -1, 1);
    expect(miss).toEqual([]);
    const hit = expectCertified([0.9999999 ** 2 - 1, 0, 1], -1, 1);
    expect(hit.length).toBe(2);
  });
});

describe("realRoots: regressions found by fast-check (shrunk)", () => {
  it("t³ + 1.5e-323 t²: the exact double root 0 next to a subnormal root (c1² underflows)", () => {
    expect(realRoots([0, 0, 1.5e-323, 1], -1, 1)).toEqual([-1.5e-323, 0]);
  });
  it("t²(t + 1e-4)²: Halley's step vanishing at a critical point of p' is not convergence", () => {
    const c = [0, 0, 9.999999999999999e-9, 0.00019999999999999998, 1];
    const r = realRoots(c, -1, 1);
    expect(r.length).toBe(2);
    expect(r[1]).toBe(0);
    expect(r[0] as number).toBeCloseTo(-1e-4, 12);
  });
});

describe("realRoots: more regressions (fast-check, seed 824665292)", () => {
  it("t(t − 3.53125)(t − 4.5)²(t + 1.0625): the exact double root 4.5 although the structural critical point is ~160 ulps off", () => {
    const c = fromRoots([0, 3.53125, 4.5, 4.5, -1.0625]);
    expect(exactPolySign(c, 4.5)).toBe(0);
    expect(realRoots(c, 0, 5)).toEqual([0, 3.53125, 4.5]);
  });
});

describe("realRoots: regression (fast-check clusters)", () => {
  it("(t − 10)²(t − 10 − 6e-11) rounded: the exact double root 10 next to a root 6e-11 away", () => {
    // The critical points 10 and 10 + 4e-11 are told apart only with an accurate discriminant.
    const c = [-1000.0000000059998, 300.00000000119996, -30.00000000006, 1];
    expect(exactPolySign(c, 10)).toBe(0);
    expect(realRoots(c, 9, 11)).toEqual([10, 10.000000000059998]);
  });
});

describe("realRoots: regression (fast-check clusters, a rounded 4-fold cluster)", () => {
  it("roots c + {1, 1, −3, 3}·1e-7 near −10: the critical point ~1e-4 off is corrected by exact p′ signs", () => {
    const c = [9999.999799996767, 3999.999939999031, 599.9999939999032, 39.99999979999677, 1];
    const lo = -10.999999999999194;
    const hi = -8.999999999999194;
    const r = expectCertified(c, lo, hi, 64);
    expect(r.length).toBe(2);
    expect(r[0]).toBe(-10);
  });
});

describe("realRoots: regressions (fast-check clusters sampled at the cluster's own scale)", () => {
  it("−10 + {−3, 1, 3, −1}·1e-5: roots on both sides of an exact double root found by exact p′ signs", () => {
    const c = [9999.999999900001, 3999.99999998, 599.999999999, 40, 1];
    const r = expectCertified(c, -10.00005, -9.99995, 64);
    expect(r.length).toBe(3);
    expect(r[1]).toBe(-10);
    expect(realRoots(c, -11, -9)).toEqual(r);
  });
  it("10 + {1, 3, −2, −1}·1e-6: the search goes on beyond an exact critical point still at noise level", () => {
    const c = [10000.000999996564, -4000.0002999990397, 600.000029999911, -40.00000099999727, 1];
    const ctr = 9.999999999999316;
    const r = expectCertified(c, ctr - 5e-6, ctr + 5e-6, 64);
    expect(r.length).toBe(3);
    expect(realRoots(c, ctr - 1, ctr + 1)).toEqual(r);
  });
});

/** The roots, each within 4 ulps of an exact root (exact BigInt signs), and no exact zero at a non-root. */
function expectRootsWithin4Ulps(c: readonly number[], roots: readonly number[]): void {
  for (const r of roots) expect(ulpsToExactRoot(c, r), `root ${r} of ${c}`).toBeLessThanOrEqual(4);
}

describe("realRoots: unbounded intervals keep small roots (audit of session 19)", () => {
  it("x² − c·x + 1 on [0, ∞): the small root ≈ 1/c to 4 ulps for c up to 1e308, never the non-root 0", () => {
    for (const c of [1e150, 1e155, 1e158, 1e160, 1e165, 1e200, 1e300, 1e308]) {
      const coeffs = [1, -c, 1];
      const r = realRoots(coeffs, 0, Number.POSITIVE_INFINITY);
      expect(r.length, `c = ${c}: ${r}`).toBe(2);
      expectRootsWithin4Ulps(coeffs, r);
      expect(r[0]).toBe(realRoots(coeffs, 0, 1)[0]); // the same bits as on [0, 1]
      expect(realRoots([1, c, 1], Number.NEGATIVE_INFINITY, 0)).toEqual([
        -(r[1] as number),
        -(r[0] as number),
      ]);
    }
  });
  it("1 − 1e140 x² + 1e-140 x⁴ on (−∞, ∞): ±1e-70 and ±1e140, not 0", () => {
    const c = [1, 0, -1e140, 0, 1e-140];
    const r = realRoots(c, Number.NEGATIVE_INFINITY, Number.POSITIVE_INFINITY);
    expect(r.length, `${r}`).toBe(4);
    expectRootsWithin4Ulps(c, r);
    expect((r[0] as number) / -1e140).toBeCloseTo(1, 12);
    expect((r[1] as number) / -1e-70).toBeCloseTo(1, 12);
    expect((r[2] as number) / 1e-70).toBeCloseTo(1, 12);
    expect((r[3] as number) / 1e140).toBeCloseTo(1, 12);
  });
  it("x⁴ − 2^400 x³ + 1 on [0, ∞): the root near 2^-133 and the one near 2^400 (Cauchy's bound 2^400)", () => {
    const c = [1, 0, 0, -(2 ** 400), 1];
    const r = realRoots(c, 0, Number.POSITIVE_INFINITY);
    expect(r.length, `${r}`).toBe(2);
    expectRootsWithin4Ulps(c, r);
    expect((r[1] as number) / 2 ** 400).toBeCloseTo(1, 12);
  });
  it("roots from 2^-200 to 2^300: each within 4 ulps, on [0, ∞) and on [2^-300, 2^1000] alike", () => {
    const ks = [2 ** -200, 2 ** -3, 2 ** 100, 2 ** 300];
    const c = fromRoots(ks);
    const r = realRoots(c, 0, Number.POSITIVE_INFINITY);
    expect(r.length, `${r}`).toBe(4);
    expectRootsWithin4Ulps(c, r);
    for (let i = 0; i < 4; i++) expect((r[i] as number) / (ks[i] as number)).toBeCloseTo(1, 12);
    expect(realRoots(c, 2 ** -300, 2 ** 1000)).toEqual(r);
  });
});

describe("realRoots: input validation", () => {
  it("refuses coeffs that are not array-like, naming them (RangeError, like every bad argument)", () => {
    for (const bad of [5, null, undefined, {}, true]) {
      expect(() => realRoots(bad as unknown as number[], 0, 1)).toThrow(RangeError);
      expect(() => realRoots(bad as unknown as number[], 0, 1)).toThrow(
        /^realRoots\(coeffs\): must be an array-like of finite numbers \(got /,
      );
    }
    expect(() => realRoots({ length: -1 } as unknown as number[], 0, 1)).toThrow(
      /^realRoots\(coeffs\): must be/,
    );
  });

  it("refuses non-finite coefficients, naming the field", () => {
    expect(() => realRoots([1, Number.NaN, 2], 0, 1)).toThrow(
      /^realRoots\(coeffs\[1\]\): must be a finite number \(got NaN\)$/,
    );
    expect(() => realRoots([1, 2, Number.POSITIVE_INFINITY], 0, 1)).toThrow(/coeffs\[2\]/);
  });
  it("says the type of a value that is not a number (a string \"1\" read as 'got 1', like a valid number)", () => {
    expect(() => realRoots(["1", "-1"] as unknown as number[], 0, 2)).toThrow(
      'realRoots(coeffs[0]): must be a finite number (got string "1")',
    );
    expect(() => realRoots([1, 2], "0" as unknown as number, 1)).toThrow(
      'realRoots(lo): must be a number (got string "0")',
    );
  });
  it("refuses NaN ends, naming them", () => {
    expect(() => realRoots([1, 2], Number.NaN, 1)).toThrow(/^realRoots\(lo\): must be a number \(got NaN\)$/);
    expect(() => realRoots([1, 2], 0, Number.NaN)).toThrow(/^realRoots\(hi\): must be a number \(got NaN\)$/);
  });
  it("accepts any array-like (Float64Array) and leaves it untouched", () => {
    const c = new Float64Array([24, -50, 35, -10, 1]);
    expect(realRoots(c, 0, 10)).toEqual([1, 2, 3, 4]);
    expect(Array.from(c)).toEqual([24, -50, 35, -10, 1]);
  });
  it("RootSolverError is an Error with its own name", () => {
    const e = new RootSolverError("x");
    expect(e).toBeInstanceOf(Error);
    expect(e.name).toBe("RootSolverError");
  });
});

describe("evalPoly", () => {
  it("evaluates ascending coefficients by Horner", () => {
    expect(evalPoly([1, 2, 3], 2)).toBe(17);
    expect(evalPoly([], 2)).toBe(0);
    expect(evalPoly(new Float64Array([5]), 9)).toBe(5);
  });
});
