import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { exactPolySign, nextDown, nextUp } from "./exactPoly.js";
import { found, quarticRoots } from "./quartic.js";
import { realRoots, realRootsInto } from "./realRoots.js";
import { expectVerified, fcParams, fromRoots, num } from "./testSupport.js";
import { verifyRoots } from "./verifyRoots.js";

const params = fcParams("quartic.test", 400);

/** quarticRoots's answer when it settles the call (null when it hands back), checked exactly. */
function hot(c: readonly number[], lo: number, hi: number): number[] | null {
  const k = quarticRoots(c, lo, hi);
  if (k < 0) return null;
  const out = Array.from(found.subarray(0, k));
  expectVerified(c, lo, hi, out, 48);
  return out;
}

/**
 * The hot path's roots against the general path's: the same count and the same bits. Both choose,
 * of the two doubles around a root, the one with the smaller exact |p| (certify.ts closerEnd); before
 * that, two certified answers could round differently (FC_SEED=676900790: -3.3795201066592964
 * against -3.379520106659296).
 */
function expectSameRoots(hotRoots: readonly number[], general: readonly number[]): void {
  expect(hotRoots.length).toBe(general.length);
  hotRoots.forEach((x, i) => {
    const g = general[i] as number;
    expect(x, `${x} vs ${g}`).toBe(g);
  });
}

describe("quarticRoots (the quartic hot path)", () => {
  it("regression (FC_SEED=676900790): hot and general paths were one ulp apart; now the same bits", () => {
    const [dx, wx, R, hi, lo] = [
      -9.92167084239082, 1.999267578123178, 1.4953027566117185, 0.01, -4.989698754888908,
    ];
    const c = [dx * dx - R * R, 0, dx * wx, 0, (wx * wx) / 4];
    const fast = hot(c, lo, hi);
    expect(fast).not.toBeNull();
    const general = realRoots([...c, 0], lo, hi);
    expectVerified(c, lo, hi, general, 48);
    expectSameRoots(fast as number[], general);
  });

  it("collision quartics: when it settles a call, every root within 4 ulps, none missed, as the general path", () => {
    let settled = 0;
    fc.assert(
      fc.property(
        num(-10, 10),
        num(-10, 10),
        num(-10, 10),
        num(-10, 10),
        num(-2, 2),
        num(-2, 2),
        num(0.5, 3),
        num(0.01, 20),
        num(-5, 0),
        (dx, dy, ux, uy, wx, wy, R, hi, lo) => {
          if (wx === 0 && wy === 0) return true;
          const c = [
            dx * dx + dy * dy - R * R,
            2 * (dx * ux + dy * uy),
            ux * ux + uy * uy + dx * wx + dy * wy,
            ux * wx + uy * wy,
            (wx * wx + wy * wy) / 4,
          ];
          for (const a of [0, lo]) {
            const r = hot(c, a, hi);
            if (r === null) continue;
            settled++;
            expectSameRoots(r, realRoots([...c, 0], a, hi)); // length 6: the general path
          }
          return true;
        },
      ),
      params,
    );
    expect(settled).toBeGreaterThan(params.numRuns); // the hot path does settle most calls
  });

  it("products of four linear factors, roots spread or paired: settled calls are certified and complete", () => {
    let settled = 0;
    fc.assert(
      fc.property(
        // (fc.double favours values near 0, i.e. multiple roots at 0: decimals spread the roots)
        fc.array(
          fc.integer({ min: -4000, max: 4000 }).map((k) => k / 1000),
          { minLength: 4, maxLength: 4 },
        ),
        fc.oneof(
          num(-1e-3, 1e-3),
          fc.integer({ min: -1000, max: 1000 }).map((k) => k / 1000),
        ),
        fc.constantFrom(1, -0.5, 3e-7, 1e5),
        (r, gap, lead) => {
          const roots = [r[0] as number, (r[0] as number) + gap, r[2] as number, r[3] as number];
          if (hot(fromRoots(roots, lead), -5, 5) !== null) settled++;
          return true;
        },
      ),
      params,
    );
    expect(settled).toBeGreaterThan(params.numRuns / 10);
  });

  it("a root exactly at hi is reported (the hot path hands it back)", () => {
    const c = fromRoots([1, 2, 3, 4]); // exact coefficients
    expect(exactPolySign(c, 3)).toBe(0);
    expect(hot(c, 0, 3)).toBeNull();
    expect(realRoots(c, 0, 3)).toEqual([1, 2, 3]);
    expect(realRoots(c, 0, 3.5)).toEqual([1, 2, 3]);
  });

  it("a root one ulp beyond hi is not reported, one ulp inside is", () => {
    const c = fromRoots([1, 2, 3, 4]);
    expect(realRoots(c, 0, nextDown(3))).toEqual([1, 2]);
    expect(realRoots(c, 0, nextUp(3))).toEqual([1, 2, 3]);
    expect(realRoots(c, nextUp(1), 10)).toEqual([2, 3, 4]);
  });

  it("touching discs (p(lo) = 0 exactly): lo, and the later roots of a re-collision, settled in the hot path", () => {
    // Separating: only lo.
    expect(hot([0, 2, 1, 0.25, 0.0625], 0, 10)).toEqual([0]);
    // Separating, then pulled back by the acceleration (p = t(t − 2)(t − 3)·(t + 1)… exact): lo and two more.
    const c = fromRoots([0, 2, 3, -1]);
    expect(c[0]).toBe(0);
    expect(hot(c, 0, 10)).toEqual([0, 2, 3]);
    // A collision quartic built as the engine builds it, d on the contact circle, c0 exactly 0.
    const [dx, dy, ux, uy, wx, wy] = [0.6, 0.8, 1.2, 0.5, -0.9, -0.7] as const;
    const q = [
      dx * dx + dy * dy - 1,
      2 * (dx * ux + dy * uy),
      ux * ux + uy * uy + dx * wx + dy * wy,
      ux * wx + uy * wy,
      (wx * wx + wy * wy) / 4,
    ];
    const r = hot(q, 0, 10);
    expect(r).not.toBeNull();
    expect(r).toEqual(realRoots([...q, 0], 0, 10)); // the general path
  });

  it("round-off overlap at lo (p(lo) tiny, its exact sign decided exactly) is settled as the general path", () => {
    for (const c0 of [-1e-17, 1e-17, -5e-324, 5e-324]) {
      const c = [c0, 2, -1, 0.25, 0.0625];
      const r = hot(c, 0, 10);
      expect(r).not.toBeNull();
      expect(r).toEqual(realRoots([...c, 0], 0, 10));
    }
  });

  it("roots closer than the subdivision depth resolves are handed back, and realRoots still finds both", () => {
    const c = fromRoots([1, 1 + 2 ** -30, 5, 7]);
    expect(hot(c, 0, 10)).toBeNull();
    const r = realRoots(c, 0, 10);
    expect(r).toHaveLength(4);
    expect(verifyRoots(c, 0, 10, r, 64, 4).maxUlps).toBeLessThanOrEqual(4);
  });

  it("input it does not handle is handed back untouched (errors come from realRoots)", () => {
    expect(quarticRoots([1, 2, 3, 4, Number.NaN], 0, 1)).toBe(-1);
    expect(quarticRoots([1, 2, 3, 4, 0], 0, 1)).toBe(-1);
    expect(quarticRoots([1, 2, 3, 4, 5], 1, 1)).toBe(-1);
    expect(quarticRoots([1, 2, 3, 4, 5], 0, Number.NaN)).toBe(-1);
    expect(quarticRoots([1e30, -2, 3, 4, 5], 0, 1)).toBe(-1); // needs scaling
    // Every coefficient of c0's sign on t ≥ 0: settled exactly, whatever the magnitudes.
    expect(quarticRoots([1e30, 2, 3, 4, 5], 0, 1)).toBe(0);
    expect(quarticRoots([-1, 0, -3, -1e-300, -5], 2, 1e6)).toBe(0);
    expect(() => realRoots([1, 2, 3, 4, Number.NaN], 0, 1)).toThrow(/coeffs\[4\]/);
  });

  it("realRootsInto clears and fills the caller's array with realRoots's answer", () => {
    const out = [42, 43];
    const c = fromRoots([0.5, 1.5, 2.5, 3.5], -2);
    expect(realRootsInto(c, 0, 3, out)).toBe(3);
    expect(out).toEqual(realRoots(c, 0, 3));
    expect(realRootsInto([1, 0, 1], 0, 3, out)).toBe(0);
    expect(out).toEqual([]);
  });

  it("realRootsInto replaces longer, shorter and equal old contents through the quartic hot path", () => {
    const c2 = fromRoots([0.25, 0.75, 5, 6], 1); // two roots in [0, 1]
    const c4 = fromRoots([0.1, 0.3, 0.6, 0.9], 1); // four roots in [0, 1]
    const none = [1, 0, 1, 0, 1]; // no real root
    // All three settled by the hot path (not handed to the general method):
    expect([quarticRoots(c2, 0, 1), quarticRoots(c4, 0, 1), quarticRoots(none, 0, 1)]).toEqual([2, 4, 0]);
    const out = [9, 9, 9, 9, 9, 9];
    expect(realRootsInto(c2, 0, 1, out)).toBe(2); // shrinks from 6
    expect(out).toEqual(realRoots(c2, 0, 1));
    expect(realRootsInto(c4, 0, 1, out)).toBe(4); // grows from 2
    expect(out).toEqual(realRoots(c4, 0, 1));
    expect(realRootsInto(c4, 0, 1, out)).toBe(4); // same length
    expect(out).toEqual(realRoots(c4, 0, 1));
    expect(out.length).toBe(4);
    expect(realRootsInto(none, 0, 1, out)).toBe(0);
    expect(out).toEqual([]);
    expect(() => realRootsInto([1, 2, 3, 4, Number.NaN], 0, 1, out)).toThrow(/coeffs\[4\]/);
  });
});
