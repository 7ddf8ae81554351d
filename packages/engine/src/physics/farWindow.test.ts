// farWindow may only narrow the far part to a window that still holds every time at which the pair
// is within the contact distance (it is a filter before the exact search). The property samples
// random accelerated motions densely and prints its seed (FC_SEED replays).
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { fcParams } from "../roots/testSupport.js";
import { farWindow } from "./farWindow.js";

const INF = Number.POSITIVE_INFINITY;
const out = new Float64Array(2);

describe("farWindow", () => {
  it("holds every sampled time at which the pair is within the contact distance", () => {
    const params = fcParams("far window", 300);
    const v = fc.double({ min: -50, max: 50, noNaN: true });
    let touching = 0;
    fc.assert(
      fc.property(
        v,
        v,
        v,
        v,
        v,
        v,
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        (dx, dy, ux, uy, wx, wy, R) => {
          fc.pre(wx !== 0 || wy !== 0);
          const open = farWindow(dx, dy, ux, uy, wx, wy, R, 0, 20, out);
          for (let i = 0; i <= 4000; i++) {
            const tau = i * 0.005;
            const x = dx + tau * (ux + 0.5 * wx * tau);
            const y = dy + tau * (uy + 0.5 * wy * tau);
            if (x * x + y * y > R * R) continue;
            touching++;
            expect(open, `tau ${tau}`).toBe(true);
            expect(out[0], `tau ${tau}`).toBeLessThanOrEqual(tau);
            expect(out[1], `tau ${tau}`).toBeGreaterThanOrEqual(tau);
          }
        },
      ),
      params,
    );
    expect(touching).toBeGreaterThan(0);
  });

  it("closes for a disc falling past a point, and opens around the fall onto it", () => {
    // Point minus disc: the disc at (5, 100) falls under gravity 10, the point is at the origin.
    expect(farWindow(-5, -100, 0, 0, 0, 10, 1, 0, INF, out)).toBe(false);
    expect(farWindow(-0.5, -100, 0, 0, 0, 10, 1, 0, INF, out)).toBe(true);
    // It reaches the point at tau = sqrt(20) ~ 4.47; the window lies around that.
    expect(out[0]).toBeLessThan(Math.sqrt((2 * 99) / 10));
    expect(out[1]).toBeGreaterThan(Math.sqrt((2 * 101) / 10));
    expect(out[1]).toBeLessThan(5);
  });
});
