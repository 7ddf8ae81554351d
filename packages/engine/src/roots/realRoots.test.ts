// realRoots's contract case by case: each degree, the interval's ends, multiple roots, a dropped
// degree and extreme scales, the refusal of bad input, and evalPoly. The hard published cases, the
// shrunk fast-check regressions and unbounded intervals: realRoots.hardCases.test.ts; random
// polynomials: realRoots.prop.test.ts.
import { describe, expect, it } from "vitest";
import { RootSolverError } from "./bracket.js";
import { exactDerivativeSign, exactPolySign, nextDown, nextUp, ulpsToExactRoot } from "./exactPoly.js";
import { evalPoly, realRoots } from "./realRoots.js";
import { expectCertified, fromRoots } from "./testSupport.js";

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
      'realRoots(coeffs[0]): must be a finite number (got the string "1")',
    );
    expect(() => realRoots([1, 2], "0" as unknown as number, 1)).toThrow(
      'realRoots(lo): must be a number (got the string "0")',
    );
    // Review of session 29: null and objects read "(got object null)", "(got object [object Object])".
    expect(() => realRoots(null as unknown as number[], 0, 1)).toThrow(
      "realRoots(coeffs): must be an array-like of finite numbers (got null)",
    );
    expect(() => realRoots([1, {}] as unknown as number[], 0, 1)).toThrow(
      "realRoots(coeffs[1]): must be a finite number (got an object)",
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
