import { describe, expect, it } from "vitest";
import { exactDerivativeSign, exactPolySign, nextDown, nextUp, ulpsToExactRoot } from "./exactPoly.js";

describe("nextUp / nextDown", () => {
  it("steps one ulp in the binade of 1", () => {
    expect(nextUp(1)).toBe(1 + 2 ** -52);
    expect(nextDown(1)).toBe(1 - 2 ** -53);
    expect(nextUp(-1)).toBe(-1 + 2 ** -53);
    expect(nextDown(-1)).toBe(-1 - 2 ** -52);
  });
  it("crosses zero through the subnormals, with both zeros", () => {
    expect(nextUp(0)).toBe(Number.MIN_VALUE);
    expect(nextUp(-0)).toBe(Number.MIN_VALUE);
    expect(nextDown(0)).toBe(-Number.MIN_VALUE);
    expect(nextUp(-Number.MIN_VALUE)).toBe(-0); // IEEE 754: nextUp(−min subnormal) = −0
    expect(nextDown(Number.MIN_VALUE)).toBe(0);
  });
  it("crosses binade boundaries and reaches the infinities", () => {
    expect(nextUp(2 - 2 ** -52)).toBe(2);
    expect(nextDown(2)).toBe(2 - 2 ** -52);
    expect(nextUp(Number.MAX_VALUE)).toBe(Number.POSITIVE_INFINITY);
    expect(nextDown(Number.NEGATIVE_INFINITY)).toBe(Number.NEGATIVE_INFINITY);
    expect(nextUp(Number.NEGATIVE_INFINITY)).toBe(-Number.MAX_VALUE);
    expect(Number.isNaN(nextUp(Number.NaN))).toBe(true);
  });
});

describe("exactPolySign", () => {
  it("is exact where floating-point evaluation is pure noise: (t-1)^4 near 1", () => {
    const c = [1, -4, 6, -4, 1];
    const x = 1 + 2 ** -40; // p(x) = 2^-160 > 0 exactly; plain Horner returns 0 or noise
    expect(exactPolySign(c, x)).toBe(1);
    expect(exactPolySign(c, 1)).toBe(0);
    expect(exactPolySign([-1, 0, 1], 1 - 2 ** -53)).toBe(-1);
  });
  it("takes the coefficients at their exact double values (0.1 is not 1/10)", () => {
    // 0.1 as a double is slightly above 1/10, so 10·0.1 − 1 > 0 exactly although fl(10*0.1) = 1.
    expect(exactPolySign([-1, 0.1], 10)).toBe(1);
    expect(0.1 * 10 - 1).toBe(0);
  });
  it("handles subnormal and huge values without overflow", () => {
    expect(exactPolySign([-(2 ** -1074), 1], 2 ** -1074)).toBe(0);
    expect(exactPolySign([-Number.MAX_VALUE, 0, 0, 0, 1], 2 ** 256)).toBe(1);
    expect(exactPolySign([1, 0, 0, 0, -1], Number.MAX_VALUE)).toBe(-1);
  });
  it("gives the empty polynomial the sign 0", () => {
    expect(exactPolySign([], 3)).toBe(0);
  });
  it("refuses non-finite input, naming the field", () => {
    expect(() => exactPolySign([1, Number.NaN], 1)).toThrow(/coeffs\[1\]/);
    expect(() => exactPolySign([1, 2], Number.POSITIVE_INFINITY)).toThrow(
      /^exactPolySign\(x\): must be a finite number \(got Infinity\)$/,
    );
  });
  it("names the function and shows what was given as the engine's other refusals do", () => {
    // Review of session 29: a string "1" was refused as "x: must be a finite number (got 1)", an
    // object as "(got [object Object])", without the function's name, and null coefficients threw
    // "Cannot read properties of null (reading 'length')".
    const bad: [() => unknown, string][] = [
      [
        () => exactPolySign([1, 2], "1" as unknown as number),
        'exactPolySign(x): must be a finite number (got the string "1")',
      ],
      [
        () => exactPolySign(["1", 2] as unknown as number[], 1),
        'exactPolySign(coeffs[0]): must be a finite number (got the string "1")',
      ],
      [
        () => exactDerivativeSign([1, {}] as unknown as number[], 0),
        "exactDerivativeSign(coeffs[1]): must be a finite number (got an object)",
      ],
      [() => ulpsToExactRoot([1, 2], Number.NaN), "ulpsToExactRoot(x): must be a finite number (got NaN)"],
      [
        () => exactPolySign(null as unknown as number[], 1),
        "exactPolySign(coeffs): must be an array-like of finite numbers (got null)",
      ],
      [
        () => exactDerivativeSign(5 as unknown as number[], 1),
        "exactDerivativeSign(coeffs): must be an array-like of finite numbers (got 5)",
      ],
    ];
    for (const [call, message] of bad) {
      expect(call).toThrow(RangeError);
      expect(call).toThrow(message);
    }
  });
});

describe("exactDerivativeSign", () => {
  it("is the sign of c1 + 2 c2 x + 3 c3 x² + …", () => {
    // p = t³ − 3t: p' = 3t² − 3, zero at ±1, negative between.
    const c = [0, -3, 0, 1];
    expect(exactDerivativeSign(c, 1)).toBe(0);
    expect(exactDerivativeSign(c, 0.5)).toBe(-1);
    expect(exactDerivativeSign(c, nextUp(1))).toBe(1);
    expect(exactDerivativeSign([7], 2)).toBe(0);
  });
});

describe("ulpsToExactRoot", () => {
  it("is 0 at an exact root and k at k ulps from a double root of a linear polynomial", () => {
    expect(ulpsToExactRoot([-3, 1], 3)).toBe(0);
    expect(ulpsToExactRoot([-3, 1], nextUp(nextUp(3)))).toBe(2);
    expect(ulpsToExactRoot([-3, 1], nextDown(3))).toBe(1);
  });
  it("is 1 next to a root that is not a double (between two doubles)", () => {
    // 0.1·t − 1: the root 1/0.1 lies strictly between two doubles near 10.
    const c = [-1, 0.1];
    const r = 1 / 0.1;
    expect(exactPolySign(c, r)).not.toBe(0);
    expect(ulpsToExactRoot(c, r)).toBe(1);
  });
  it("is Infinity beyond maxUlps and where there is no root at all", () => {
    expect(ulpsToExactRoot([-3, 1], 3 + 2 ** -40, 8)).toBe(Number.POSITIVE_INFINITY);
    expect(ulpsToExactRoot([1, 0, 1], 0)).toBe(Number.POSITIVE_INFINITY);
  });
});
