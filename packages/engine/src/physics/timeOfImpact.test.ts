// Contact times are a function of the two motions alone: evaluating a pair at any moment before
// its contact, or a few ulps after it (a stale prediction popped there, a World rebuilt from a
// keyframe, the grid bringing the pair together late), gives the same bits. The property prints
// its seed; set FC_SEED to explore other seeds.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { nextUp } from "../roots/nextDouble.js";
import { seedFor } from "../timeline/testSupport.js";
import { discDiscTime, discLineCrossings } from "./timeOfImpact.js";

const SEED = seedFor("contact time");
const INF = Number.POSITIVE_INFINITY;

/** `lo` moved k ulps up. */
function ulpsAfter(x: number, k: number): number {
  let y = x;
  for (let i = 0; i < k; i++) y = nextUp(y);
  return y;
}

describe("contact time does not depend on when it is evaluated", () => {
  it("disc-disc, uniform or accelerated: any lo before the contact or up to 4 ulps after it gives the same time", () => {
    const coord = fc.double({ min: -20, max: 20, noNaN: true });
    const acc = fc.oneof(fc.constant(0), fc.double({ min: -5, max: 5, noNaN: true }));
    let checked = 0;
    fc.assert(
      fc.property(
        // Relative velocity mostly towards the other disc (s > 0), plus a sideways part.
        fc.tuple(coord, coord, fc.double({ min: -0.5, max: 2, noNaN: true }), coord, coord, acc, acc),
        fc.double({ min: 0.1, max: 5, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.integer({ min: 0, max: 4 }),
        ([dx, dy, k, ex, ey, wx, wy], R, frac, ulps) => {
          fc.pre(dx * dx + dy * dy > R * R * 1.0001);
          const ux = -k * dx + 0.2 * ex;
          const uy = -k * dy + 0.2 * ey;
          const tb = 0.75;
          const tau = discDiscTime(dx, dy, ux, uy, wx, wy, R, 0, 1e3);
          if (tau === INF) return;
          checked++;
          const t = tb + tau;
          for (const now of [tb + frac * tau, ulpsAfter(t, ulps)]) {
            const late = discDiscTime(dx, dy, ux, uy, wx, wy, R, now - tb, 1e3);
            expect(late).not.toBe(INF);
            expect(Math.max(tb + late, now)).toBe(Math.max(t, now));
          }
        },
      ),
      { seed: SEED, numRuns: 2000, verbose: true },
    );
    expect(checked).toBeGreaterThan(100); // about 150 of the 2,000 scenes meet in the window
  });

  it("disc-line: a contact under way returns the crossing, not the moment of evaluation", () => {
    // A disc of radius 1 at y = 3 moving down at speed 2 onto the line y = 0 crosses at tau = 1.
    const out = new Float64Array(2);
    discLineCrossings(0, 3, 0, -2, 0, 0, 0, 0, 0, 1, 1, 0, INF, out);
    expect(out[0]).toBe(1);
    discLineCrossings(0, 3, 0, -2, 0, 0, 0, 0, 0, 1, 1, ulpsAfter(1, 2), INF, out);
    expect(out[0]).toBe(1);
    // Long after the crossing (deep in the line) it is still that crossing; the caller clamps to now.
    discLineCrossings(0, 3, 0, -2, 0, 0, 0, 0, 0, 1, 1, 1.25, INF, out);
    expect(out[0]).toBe(1);
    // A disc that started touching and approaches has no crossing: contact at lo.
    discLineCrossings(0, 1, 0, -2, 0, 0, 0, 0, 0, 1, 1, 0, INF, out);
    expect(out[0]).toBe(0);
  });
});

describe("far apart", () => {
  it("a pair 1e8 to 1e12 contact distances apart still meets (the discriminant cancelled to noise: review)", () => {
    // Discs of radius 0.5 (contact distance 1) at distance d, closing at speed 1: contact at d - 1.
    for (const d of [1e7, 1e8, 1e10, 1e12]) {
      const tau = discDiscTime(d, 0, -1, 0, 0, 0, 1, 0, INF);
      expect(Math.abs(tau - (d - 1)), `d = ${d}`).toBeLessThanOrEqual(4e-16 * d);
    }
    // Off the line of centres by 0.9 (still hitting) and by 1.1 (missing).
    const hit = discDiscTime(1e8, 0.9, -1, 0, 0, 0, 1, 0, INF);
    expect(Math.abs(hit - (1e8 - Math.sqrt(1 - 0.81)))).toBeLessThanOrEqual(1e-7);
    expect(discDiscTime(1e8, 1.1, -1, 0, 0, 0, 1, 0, INF)).toBe(INF);
  });
});
