import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { exactPolySign, nextUp } from "./exactPoly.js";
import { found, quarticRoots } from "./quartic.js";
import { realRoots } from "./realRoots.js";
import { expectVerified, fcParams } from "./testSupport.js";
import { isGrazingRoot } from "./verifyRoots.js";

const params = fcParams("quarticPieces.test", 300);

/**
 * x⁴ + … with p′ = 4(x − x2)(x − xc)(x − x3), x3 = −(x2 + xc) (so c3 = 0), and p(xc) = −eps: for
 * x2 just outside [lo, hi] and xc inside, p has one flat critical point xc in the interval (p″(xc)
 * is small) and, for a small eps, two close roots around it. Exact for few-bit xc, x2.
 */
function flatMinimum(xc: number, x2: number, eps: number): number[] {
  const s2 = x2 * xc - (x2 + xc) * (x2 + xc);
  const s3 = -x2 * xc * (x2 + xc);
  const c2 = 2 * s2;
  const c1 = -4 * s3;
  const c0 = -(((xc * xc + c2) * xc + c1) * xc) - eps;
  return [c0, c1, c2, 0, 1];
}

/**
 * Exact sign changes of p over a grid of doubles x0 + k·step (|k| ≤ 64) clipped to [lo, hi]: each
 * needs a root between
 * its grid points, or a grazing report on the grid (p at rounding-noise level at a critical point
 * stands for the close pair under realRoots's grazing contract, see verifyRoots.ts).
 */
function expectGridCovered(
  c: readonly number[],
  lo: number,
  hi: number,
  x0: number,
  step: number,
  roots: readonly number[],
) {
  const at = (k: number) => Math.min(hi, Math.max(lo, x0 + k * step));
  let px = at(-64);
  const grazing = roots.some((r) => r >= px && r <= at(64) && isGrazingRoot(c, r));
  let ps = exactPolySign(c, px);
  for (let k = -63; k <= 64; k++) {
    const x = at(k);
    const s = exactPolySign(c, x);
    if (s !== ps && !grazing && !roots.some((r) => r >= px && r <= x)) {
      expect.fail(`sign change of ${c} in [${px}, ${x}] missed: roots ${roots}`);
    }
    px = x;
    ps = s;
  }
}

describe("unimodal (quarticPieces.ts): p's sign at its only critical point is certified", () => {
  it("regression: two roots 2·10⁻⁶ apart at a flat minimum, missed from Halley's early estimate", () => {
    // p′ = 4(x − (1 − 2⁻⁹))(x − 1)(x + 2 − 2⁻⁹): minimum at 1, p(1) = −2⁻⁴⁵, p″(1) ≈ 0.023.
    // Halley on p′ stopped at 1 + 1.6e-5, where p > 0 (certified): both roots were dropped.
    const c = flatMinimum(1, 1 - 2 ** -9, 2 ** -45);
    expect(c).toEqual([-2.9882888793945597, 7.9765777587890625, -5.988288879394531, 0, 1]);
    const lo = 1 - 2 ** -10;
    expect([exactPolySign(c, lo), exactPolySign(c, 1), exactPolySign(c, 3)]).toEqual([1, -1, 1]);
    const roots = realRoots(c, lo, 3);
    expect(roots.length).toBe(2);
    expectVerified(c, lo, 3, roots, 48);
    const k = quarticRoots(c, lo, 3);
    if (k >= 0) expect(Array.from(found.subarray(0, k))).toEqual(roots); // hot path: all or nothing
  });

  it("property: flat extrema with close roots (or none) around them, none missed on a fine grid", () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 8, max: 64 }), // xc = k/16
        fc.integer({ min: 4, max: 20 }), // d = 2^-j · m/8
        fc.integer({ min: 1, max: 8 }),
        fc.integer({ min: 30, max: 80 }), // eps = ±2^-e
        fc.boolean(),
        fc.constantFrom(0.25, 0.5, 0.875),
        fc.constantFrom(1 / 64, 1 / 4, 2),
        fc.boolean(), // mirror x → −x
        fc.boolean(), // −p
        (k, j, m, e, negEps, loF, hiF, mirror, flip) => {
          const xc = k / 16;
          const d = 2 ** -j * (m / 8);
          const eps = (negEps ? -1 : 1) * 2 ** -e;
          let c = flatMinimum(xc, xc - d, eps);
          let lo = xc - d * loF;
          let hi = xc + hiF;
          let x0 = xc;
          if (mirror) {
            c = [c[0], -(c[1] as number), c[2], -(c[3] as number), c[4]] as number[];
            [lo, hi, x0] = [-hi, -lo, -xc];
          }
          if (flip) c = c.map((v) => -v);
          const roots = realRoots(c, lo, hi);
          expectVerified(c, lo, hi, roots, 48, true); // (|eps| at noise level: a grazing report)
          // The roots' half-distance √(2|eps|/p″(xc)), p″(xc) = 4d(2xc + x2): a grid 16 steps a root.
          const half = Math.sqrt((2 * Math.abs(eps)) / (4 * d * (3 * xc - d)));
          const step = Math.max(half / 16, nextUp(Math.abs(x0)) - Math.abs(x0));
          expectGridCovered(c, lo, hi, x0, step, roots);
          const n = quarticRoots(c, lo, hi);
          if (n >= 0) expect(Array.from(found.subarray(0, n))).toEqual(roots);
          return true;
        },
      ),
      params,
    );
  });
});
