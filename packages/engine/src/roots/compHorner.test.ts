import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { compHorner, compHornerDD, hornerBound } from "./compHorner.js";
import { exactDerivativeSign, exactPolySign, nextUp } from "./exactPoly.js";
import { fcParams, fromRoots, num } from "./testSupport.js";

const params = fcParams("compHorner.test", 1000);

/** Coefficients of ∏(t − rᵢ) in double arithmetic, and points a few ulps around the first root. */
const nearRoot = fc
  .record({
    roots: fc.array(num(-10, 10), { minLength: 1, maxLength: 6 }),
    ulps: fc.integer({ min: -40, max: 40 }),
  })
  .map(({ roots, ulps }) => {
    const c = fromRoots(roots);
    let x = roots[0] as number;
    for (let k = 0; k < Math.abs(ulps); k++) x = ulps > 0 ? nextUp(x) : -nextUp(-x);
    return { c, x };
  });

describe("Horner error bounds (checked against exact signs)", () => {
  it("whenever |value| > bound, the sign is the exact sign (plain and compensated), near roots", () => {
    const out = new Float64Array(5);
    let decidedPlain = 0;
    let decidedComp = 0;
    fc.assert(
      fc.property(nearRoot, ({ c, x }) => {
        const n = c.length - 1;
        const exact = exactPolySign(c, x);
        hornerBound(c, n, x, out);
        if (Math.abs(out[0] as number) > (out[1] as number)) {
          decidedPlain++;
          expect(Math.sign(out[0] as number)).toBe(exact);
        }
        compHorner(c, n, x, out);
        if (Math.abs(out[0] as number) > (out[1] as number) || out[1] === 0) {
          decidedComp++;
          expect(Math.sign(out[0] as number) + 0).toBe(exact);
        }
      }),
      { ...params, numRuns: 2 * params.numRuns },
    );
    // The compensated evaluation decides far more points than the plain one (this is its purpose).
    expect(decidedComp).toBeGreaterThan(decidedPlain);
  });

  it("the compensated bound is 0 only when the evaluation was exact", () => {
    const out = new Float64Array(5);
    compHorner([-6, 11, -6, 1], 3, 2, out); // (t−1)(t−2)(t−3) at 2: every operation exact
    expect(out[0]).toBe(0);
    expect(out[1]).toBe(0);
    compHorner([-1, 0.1], 1, 10, out); // 0.1·10 − 1 rounds: not exact
    expect(out[1]).toBeGreaterThan(0);
    expect(exactPolySign([-1, 0.1], 10)).toBe(1);
  });

  it("double-double coefficients (derivatives i·cᵢ kept exact) give the exact derivative sign", () => {
    const out = new Float64Array(5);
    let decided = 0;
    fc.assert(
      fc.property(nearRoot, ({ c, x }) => {
        const n = c.length - 1;
        if (n < 2) return;
        const hi: number[] = [];
        const lo: number[] = [];
        for (let i = 1; i <= n; i++) {
          const v = i * (c[i] as number);
          hi.push(v);
          // i·c exactly = v + err: small integers times a double, error by splitting c.
          const t = 134217729 * (c[i] as number);
          const ch = t - (t - (c[i] as number));
          const cl = (c[i] as number) - ch;
          lo.push(i * cl - (v - i * ch));
        }
        compHornerDD(hi, lo, n - 1, x, out);
        if (Math.abs(out[0] as number) > (out[1] as number)) {
          decided++;
          expect(Math.sign(out[0] as number)).toBe(exactDerivativeSign(c, x));
        }
      }),
      params,
    );
    // only decided points are checked: a bound grown useless (Infinity) would check none (review of
    // session 20); about half the points are decided
    expect(decided).toBeGreaterThan(params.numRuns / 5);
  });
});
