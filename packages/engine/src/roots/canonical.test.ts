// Of the two doubles around a root, realRoots returns the one with the smaller exact |p| (the
// lower one on an exact tie): certify.ts closerEnd, and the hot path's second-order model when it
// can order them. The choice is therefore the same on every path, and a polynomial in another time
// unit (t = 2^k s: coefficients c_j 2^(jk), exact) has its roots at exactly 2^-k times the bits.
// Property seeds are printed (FC_SEED replays).
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { exactAbsCompare, exactPolySign, nextDown, nextUp } from "./exactPoly.js";
import { mulPow2 } from "./pow2.js";
import { realRoots } from "./realRoots.js";
import { fcParams, num } from "./testSupport.js";

/** The root x is the canonical one of its pair: the exact sign changes next to it, and its |p| is smaller. */
function expectCanonical(c: readonly number[], x: number, label: string): void {
  const s = exactPolySign(c, x);
  if (s === 0) return; // an exact root
  const up = nextUp(x);
  const down = nextDown(x);
  const other = exactPolySign(c, up) !== s ? up : exactPolySign(c, down) !== s ? down : null;
  expect(other, `${label}: no sign change next to ${x}`).not.toBeNull();
  const cmp = exactAbsCompare(c, x, other as number);
  expect(cmp < 0 || (cmp === 0 && x < (other as number)), `${label}: ${other} is closer than ${x}`).toBe(
    true,
  );
}

/** c_j 2^(jk): the same polynomial in s with t = 2^k s. */
const rescaled = (c: readonly number[], k: number) => c.map((cj, j) => mulPow2(cj, j * k));

describe("canonical roots", () => {
  it("near ties pick the double with the smaller exact |p| (scale audit's reproducers: a gravity and a friction pair)", () => {
    const gravity = [
      1042.3607989764644, -972.4874408238786, 121.38834417551213, 43.4239272639132, 5.7949319717119385,
    ];
    const g = realRoots(gravity, 0, Number.POSITIVE_INFINITY);
    expect(g[0]).toBe(1.7301252104198275); // was ...273, 0.52 ulp below the exact root
    const friction = [
      762.7051509835807, -834.5175536656798, 242.20265618351374, -8.746260924958602, 0.08491413779652843,
    ];
    const f = realRoots(friction, 0, 19.889481291828325);
    for (const [c, roots, label] of [
      [gravity, g, "gravity"],
      [friction, f, "friction"],
    ] as const)
      for (const x of roots) expectCanonical(c, x, label);
    // In other time units, the same bits (the hot path at one scale, the general one at another).
    for (const k of [-31, -3, 10, 40]) {
      expect(realRoots(rescaled(gravity, k), 0, Number.POSITIVE_INFINITY).map((x) => mulPow2(x, k))).toEqual(
        g,
      );
      expect(
        realRoots(rescaled(friction, k), 0, mulPow2(19.889481291828325, -k)).map((x) => mulPow2(x, k)),
      ).toEqual(f);
    }
  });

  it("collision quartics: every root is canonical, and bit-identical in any power-of-two time unit", () => {
    const params = fcParams("canonical", 1500);
    const v = num(-10, 10);
    fc.assert(
      fc.property(
        v,
        v,
        v,
        v,
        num(-3, 3),
        num(-3, 3),
        num(0.2, 3),
        fc.integer({ min: -60, max: 60 }),
        (dx, dy, ux, uy, wx, wy, R, k) => {
          const c = [
            dx * dx + dy * dy - R * R,
            2 * (dx * ux + dy * uy),
            ux * ux + uy * uy + (dx * wx + dy * wy),
            ux * wx + uy * wy,
            0.25 * (wx * wx + wy * wy),
          ];
          const roots = realRoots(c, 0, 20);
          for (const x of roots) expectCanonical(c, x, "roots");
          const scaled = realRoots(rescaled(c, k), 0, mulPow2(20, -k)).map((x) => mulPow2(x, k));
          expect(scaled).toEqual(roots);
        },
      ),
      params,
    );
  });
});
