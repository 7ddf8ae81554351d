// farWindows may only narrow the far part to a window that still holds every time at which the pair
// is within the contact distance (it is a filter before the exact search). The property samples
// random accelerated motions densely and prints its seed (FC_SEED replays).
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { fcParams } from "../roots/testSupport.js";
import { farWindows } from "./farWindow.js";

const INF = Number.POSITIVE_INFINITY;
const out = new Float64Array(4);

/** Whether tau lies in one of the n windows in out. */
const inWindow = (n: number, tau: number) =>
  (n > 0 && (out[0] as number) <= tau && tau <= (out[1] as number)) ||
  (n > 1 && (out[2] as number) <= tau && tau <= (out[3] as number));

describe("farWindows", () => {
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
          const n = farWindows(dx, dy, ux, uy, wx, wy, R, 0, 20, out);
          for (let i = 0; i < n; i++) {
            // Inside every window the pair stays within 2 sqrt(2) R (sampled at both ends and the middle).
            for (const f of [0, 0.5, 1]) {
              const tau = (1 - f) * (out[2 * i] as number) + f * (out[2 * i + 1] as number);
              const x = dx + tau * (ux + 0.5 * wx * tau);
              const y = dy + tau * (uy + 0.5 * wy * tau);
              expect(Math.hypot(x, y), `window ${i} at ${tau}`).toBeLessThanOrEqual(
                2 * Math.SQRT2 * R * (1 + 1e-9),
              );
            }
          }
          for (let i = 0; i <= 4000; i++) {
            const tau = i * 0.005;
            const x = dx + tau * (ux + 0.5 * wx * tau);
            const y = dy + tau * (uy + 0.5 * wy * tau);
            if (x * x + y * y > R * R) continue;
            touching++;
            expect(inWindow(n, tau), `tau ${tau}`).toBe(true);
          }
        },
      ),
      params,
    );
    expect(touching).toBeGreaterThan(0);
  });

  it("closes for a disc falling past a point, and opens around the fall onto it", () => {
    // Point minus disc: the disc at (5, 100) falls under gravity 10, the point is at the origin.
    expect(farWindows(-5, -100, 0, 0, 0, 10, 1, 0, INF, out)).toBe(0);
    expect(farWindows(-0.5, -100, 0, 0, 0, 10, 1, 0, INF, out)).toBe(1);
    // Level with the point at tau = sqrt(20); the window runs from 2 R above it to 2 R below it.
    expect(out[0]).toBeCloseTo(Math.sqrt((2 * 98) / 10), 12);
    expect(out[1]).toBeCloseTo(Math.sqrt((2 * 102) / 10), 12);
  });

  it("gives two windows when the path passes the other body twice", () => {
    // Thrown up past a point 10 above with speed 20 under gravity 10 (point minus disc: d = (0, 10),
    // u = (0, -20), w = (0, 10)): level with it at tau = 2 - sqrt(2) and 2 + sqrt(2).
    expect(farWindows(0, 10, 0, -20, 0, 10, 1, 0, INF, out)).toBe(2);
    expect(inWindow(2, 2 - Math.SQRT2)).toBe(true);
    expect(inWindow(2, 2 + Math.SQRT2)).toBe(true);
    expect(inWindow(2, 2)).toBe(false); // the top of the throw, 10 above the point
  });

  it("a subnormal acceleration still has a unit direction (FC_SEED=1596312897: its norm underflowed to 0)", () => {
    const n = farWindows(0, 0, 0, -0.014142135637873093, 0, -5e-324, 0.1, 0, 20, out);
    expect(n).toBe(1);
    // Moving away at 0.0141 from contact: within 0.2 of it until tau = 0.2 / 0.0141 = 14.1.
    expect(out[0]).toBe(0);
    expect(out[1]).toBeCloseTo(0.2 / 0.014142135637873093, 9);
  });
});
