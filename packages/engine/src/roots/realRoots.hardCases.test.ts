// realRoots on the hard cases: published ill-conditioned polynomials (clusters, Wilkinson's, roots
// over many orders of magnitude), the regressions fast-check found (shrunk), and unbounded
// intervals that must keep their tiny roots. Each result is certified against the exact polynomial
// of the given doubles (within 4 ulps of an exact root, no exact sign change missed).
import { describe, expect, it } from "vitest";
import { exactPolySign, ulpsToExactRoot } from "./exactPoly.js";
import { realRoots } from "./realRoots.js";
import { expectCertified, fromRoots } from "./testSupport.js";

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
