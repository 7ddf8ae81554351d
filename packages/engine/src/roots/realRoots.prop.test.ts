import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { exactPolySign } from "./exactPoly.js";
import { realRoots } from "./realRoots.js";
import { expectVerified, fcParams, fromRoots, num } from "./testSupport.js";

const params = fcParams("realRoots.prop.test", 300);

/**
 * The solver's guarantee on [lo, hi]: ordered; every root within 4 ulps of an exact root, except
 * grazing (double-root) reports, which must meet their own contract (an exact critical point where
 * p is within rounding noise of 0: with rounded coefficients no exact root need exist there, see
 * README "Accuracy"); no exact sign change between sample points missed.
 */
function certified(c: readonly number[], lo: number, hi: number, samples: number): boolean {
  expectVerified(c, lo, hi, realRoots(c, lo, hi), samples, true);
  return true;
}

/** A collision gap polynomial |d + u t + w t²/2|² − R², built as the engine builds it. */
const collision = fc
  .record({
    scale: fc.integer({ min: -6, max: 6 }),
    dx: num(-10, 10),
    dy: num(-10, 10),
    ux: num(-5, 5),
    uy: num(-5, 5),
    wx: num(-1, 1),
    wy: num(-1, 1),
    R: num(0.01, 5),
    hi: num(0, 20),
    kind: fc.constantFrom("quartic", "quadratic", "tinyAcceleration"),
  })
  .map((g) => {
    const s = 10 ** g.scale;
    const dx = g.dx * s;
    const dy = g.dy * s;
    const R = g.R * s;
    const ux = g.ux * s;
    const uy = g.uy * s;
    const k = g.kind === "quadratic" ? 0 : g.kind === "tinyAcceleration" ? 1e-12 : 1;
    const wx = g.wx * s * k;
    const wy = g.wy * s * k;
    const coeffs = [
      dx * dx + dy * dy - R * R,
      2 * (dx * ux + dy * uy),
      ux * ux + uy * uy + (dx * wx + dy * wy),
      ux * wx + uy * wy,
      0.25 * (wx * wx + wy * wy),
    ];
    return { coeffs, hi: g.hi };
  });

describe("realRoots properties (fast-check)", () => {
  it("collision quartics: every root within 4 ulps of an exact root, no exact sign change missed", () => {
    fc.assert(
      fc.property(collision, ({ coeffs, hi }) => certified(coeffs, 0, hi, 40)),
      params,
    );
  });

  it("exact products of linear factors (dyadic roots, exact coefficients): exactly the distinct roots", () => {
    const dyadic = fc
      .tuple(fc.integer({ min: -255, max: 255 }), fc.integer({ min: 0, max: 6 }))
      .map(([k, e]) => k / 2 ** e);
    fc.assert(
      fc.property(
        fc.array(dyadic, { minLength: 1, maxLength: 6 }),
        fc.constantFrom(1, -1, 0.5, 3, -7),
        dyadic,
        dyadic,
        (roots, lead, a, b) => {
          const lo = Math.min(a, b);
          const hi = Math.max(a, b);
          const c = fromRoots(roots, lead);
          // Precondition of this property (true by construction: few mantissa bits): exact expansion.
          for (const r of roots) expect(exactPolySign(c, r)).toBe(0);
          const expected = [...new Set(roots)].filter((r) => r >= lo && r <= hi).sort((x, y) => x - y);
          expect(realRoots(c, lo, hi)).toEqual(expected.map((r) => r + 0)); // −0 → +0
          return true;
        },
      ),
      params,
    );
  });

  it("rounded products of linear factors (any roots): certified and complete", () => {
    // Roots below 1e-60 in magnitude (other than 0) are left out on purpose: products of five of them
    // underflow, giving coefficients spread over more than 2^1000, the documented range limit.
    const root = fc.oneof(
      fc.constant(0),
      num(-100, 100).filter((x) => Math.abs(x) >= 1e-60),
    );
    fc.assert(
      fc.property(
        fc.array(root, { minLength: 1, maxLength: 5 }),
        num(0.001, 1000),
        num(-120, 120),
        num(0, 240),
        (roots, lead, lo, width) => certified(fromRoots(roots, lead), lo, lo + width, 40),
      ),
      params,
    );
  });

  it("grazing collisions: a path passing at distance R (plus a tiny offset): certified and complete", () => {
    fc.assert(
      fc.property(
        num(0.1, 10),
        num(0.1, 5),
        num(0.1, 8),
        num(-1, 1),
        num(-1e-6, 1e-6),
        (R, v, t0, w, eps) => {
          // Relative position d + u t + w t²/2 with d = (−v t0, R + eps), u = (v, 0), w = (0, w):
          // the gap |·|² − R² has a (near-)double root near t0 when w = 0 and eps = 0.
          const dx = -v * t0;
          const dy = R + eps;
          const wy = w * 1e-3;
          const c = [dx * dx + dy * dy - R * R, 2 * (dx * v), v * v + dy * wy, 0, 0.25 * wy * wy];
          return certified(c, 0, 2 * t0, 64);
        },
      ),
      params,
    );
  });

  it("clusters: roots c + k·δ with tiny δ, rounded coefficients: certified and complete", () => {
    fc.assert(
      fc.property(
        // Centres in the subnormal range are left out on purpose: there the products of the roots
        // underflow, and the doubles no longer describe a cluster (documented coefficient-range limit).
        fc.oneof(
          fc.constant(0),
          num(-10, 10).filter((x) => Math.abs(x) > 1e-60),
        ),
        fc.integer({ min: 4, max: 12 }),
        fc.array(fc.integer({ min: -3, max: 3 }), { minLength: 2, maxLength: 4 }),
        (center, e, ks) => {
          const delta = 10 ** -e;
          const roots = ks.map((k) => center + k * delta);
          const c = fromRoots(roots, 1);
          // Wide interval, and a tight one whose samples resolve the cluster itself.
          return (
            certified(c, center - 1, center + 1, 64) &&
            certified(c, center - 5 * delta, center + 5 * delta, 64)
          );
        },
      ),
      params,
    );
  });
});
