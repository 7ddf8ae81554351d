// Far contacts of accelerated pairs (friction, gravity): the quartic gap's terms grow with the square
// of the path's span, so before re-anchoring a disc dropped from 1e8 radii onto a point fell through
// it, and a ball thrown 1e8 radii up came back one radius off. Times are checked against the exact
// gap (BigInt), not against the engine's own arithmetic. Property seeds are printed (FC_SEED replays).
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { nextDown, nextUp } from "../roots/nextDouble.js";
import { fcParams } from "../roots/testSupport.js";
import { FAR_CONTACT_REACH, UNIT_ROUNDOFF } from "../tolerances.js";
import { quarticContact } from "./farContact.js";
import { exactGapSign } from "./testSupport.js";
import { discDiscTime } from "./timeOfImpact.js";

const INF = Number.POSITIVE_INFINITY;

/** x moved k ulps (k < 0: down). */
function ulps(x: number, k: number): number {
  let y = x;
  for (let i = 0; i < Math.abs(k); i++) y = k > 0 ? nextUp(y) : nextDown(y);
  return y;
}

type Pair = [dx: number, dy: number, ux: number, uy: number, wx: number, wy: number, R: number];

/**
 * The exact gap changes sign from + to - around tau, within the accuracy the design promises
 * (FAR_CONTACT_REACH): the contact position is off by at most about UNIT_ROUNDOFF * M^2 / R while
 * the path's span M (the 1-norm bound farContact.ts uses) is within the reach (or the window the
 * near part ends in), and about
 * UNIT_ROUNDOFF * M beyond it (the re-anchored closest point carries the rounding of positions of
 * size M). Divided by the closing speed, that is a time; plus a few ulps of tau.
 */
function expectCrossingNear(pair: Pair, tau: number, label: string): void {
  const [dx, dy, ux, uy, wx, wy, R] = pair;
  expect(tau, label).toBeLessThan(INF);
  const M =
    Math.abs(dx) +
    Math.abs(dy) +
    (Math.abs(ux) + Math.abs(uy)) * tau +
    0.5 * (Math.abs(wx) + Math.abs(wy)) * tau * tau;
  // The near part runs on to the end of a window it ends in, a little past the reach: 2x leeway.
  const position = 8 * UNIT_ROUNDOFF * M * (M <= 2 * FAR_CONTACT_REACH * R ? M / R : 1);
  const ex = dx + tau * (ux + 0.5 * wx * tau);
  const ey = dy + tau * (uy + 0.5 * wy * tau);
  const closing = -(ex * (ux + wx * tau) + ey * (uy + wy * tau)) / R;
  expect(closing, `${label}: approaching`).toBeGreaterThan(0);
  const slack = position / closing;
  const before = Math.min(ulps(tau, -4), tau - slack);
  const after = Math.max(ulps(tau, 4), tau + slack);
  expect(exactGapSign(dx, dy, ux, uy, wx, wy, R, before), `${label}: gap before`).toBe(1);
  expect(exactGapSign(dx, dy, ux, uy, wx, wy, R, after), `${label}: gap after`).toBe(-1);
}

describe("far contacts under gravity", () => {
  const g = 9.81;
  it("a disc dropped from 10 to 1e12 radii onto a point meets it (1e8 fell through it before)", () => {
    for (let k = 1; k <= 12; k++) {
      const H = 10 ** k;
      for (const x of [0, 0.5, -0.9]) {
        // Disc of radius 1 at (x, H) at rest, point at the origin: d = disc - point, w = gravity.
        const pair: Pair = [x, H, 0, 0, 0, -g, 1];
        expectCrossingNear(pair, discDiscTime(...pair, 0, INF), `H = 1e${k}, x = ${x}`);
      }
      // Beside the point by more than the radius: it falls past.
      expect(discDiscTime(1.01, H, 0, 0, 0, -g, 1, 0, INF), `H = 1e${k}, beside`).toBe(INF);
    }
  });

  it("a disc thrown 10 to 1e12 radii up from a point comes back onto it at the right time", () => {
    for (let k = 1; k <= 12; k++) {
      const v = Math.sqrt(2 * g * 10 ** k);
      // Starts touching the point and leaves it; the contact is the return, about 2 v / g later.
      const pair: Pair = [0.75, 1, 0, v, 0, -g, 1.25];
      const tau = discDiscTime(...pair, 0, INF);
      expectCrossingNear(pair, tau, `1e${k} up`);
      expect(Math.abs(tau - (2 * v) / g) / tau, `1e${k} up`).toBeLessThan(1e-6);
    }
  });
});

describe("far contacts under friction", () => {
  it("a disc sliding 1e3 to 1e12 contact distances to a resting one hits it when it stops past the contact, and misses when it stops short", () => {
    const a = 2; // deceleration mu g
    for (let k = 3; k <= 12; k++) {
      const L = 10 ** k;
      for (const [offset, hits] of [
        [0.5, true],
        [-0.5, false],
      ] as const) {
        // Stopping distance v^2 / (2a) = L - 1 + offset: the centres would come to L - (L - 1 + offset).
        const v = Math.sqrt(2 * a * (L - 1 + offset));
        const pair: Pair = [L, 0, -v, 0, a, 0, 1]; // resting disc minus the slider
        const tau = quarticContact(...pair, 0, v / a);
        if (hits) expectCrossingNear(pair, tau, `L = 1e${k}`);
        else expect(tau, `L = 1e${k} short`).toBe(INF);
      }
    }
  });
});

describe("the near reach's end", () => {
  it("a contact under way when evaluated past the near reach reports its crossing in the near part", () => {
    // Closing at 100 with relative deceleration 1, R = 1: the 1-norm bound d + 100 t + t^2 / 2 reaches
    // FAR_CONTACT_REACH (1024) at `near`, 0.01 after the crossing at tc.
    const v = 100;
    const a = 1;
    const delta = 0.01;
    const tc = (FAR_CONTACT_REACH - 1 - v * delta - 0.5 * a * delta * delta) / (2 * v + a * delta);
    const d = 1 + v * tc - 0.5 * a * tc * tc;
    const pair: Pair = [d, 0, -v, 0, a, 0, 1];
    const first = quarticContact(...pair, 0, v / a);
    expectCrossingNear(pair, first, "from the start");
    expect(Math.abs(first - tc)).toBeLessThan(1e-9);
    // Evaluated just before and after the reach's end (approaching from tc until the centres pass
    // at tc + 0.0105): the crossing.
    const near = tc + delta;
    for (const lo of [near - 1e-6, near, near + 1e-6])
      expect(quarticContact(...pair, lo, v / a), `lo ${lo}`).toBe(first);
    // After the centres passed, overlapping but separating (tc + 0.015), or apart (tc + 0.025, 0.03):
    // no contact (review: a fallback at the reach's end reported the crossing there).
    for (const off of [0.015, 0.025, 0.03])
      expect(quarticContact(...pair, tc + off, v / a), `tc + ${off}`).toBe(INF);
  });

  it("evaluated a few ulps before a contact right at the reach's end, the contact's own bits (review)", () => {
    // The near part's roots ended at the reach's end; evaluated just before a crossing there, the
    // gap was <= 0 by rounding and the crossing past the end unseen, so lo itself came back.
    const straight: Pair = [512.5, 0, -1, 0, 0, 1e-20, 1]; // the bound 512.5 + t reaches 1024 at 511.5
    const decelerating: Pair = [
      0.5125000000000074, 0, -3.140587902069092, 0, -12.863044461450684, -4.978630542755127e-13, 0.001,
    ];
    for (const [pair, steps] of [
      [straight, [-100, -50, -20, -10, -4, -3, -2, -1]],
      [decelerating, [-5000, -209, -20, -3, -1]],
    ] as const) {
      const first = quarticContact(...pair, 0, INF);
      expectCrossingNear(pair, first, "from the start");
      for (const k of steps) {
        // Any lo before the contact found gives its bits (the gap at lo may be <= 0 by rounding).
        expect(quarticContact(...pair, ulps(first, k), INF), `lo ${k} ulps`).toBe(first);
      }
    }
  });
});

describe("far contacts without acceleration", () => {
  it("a straight path 1e3 contact distances long (FC_SEED=827864543: the whole path was one window)", () => {
    // The property's shrunk case: w = 0 reaches quarticContact (the engine sends it the quadratic
    // path, but the function must hold on its own); contact at tau = 10.
    const v = [-2, -9.797958971132712] as const;
    const pair: Pair = [0.1 - v[0] * 10, -v[1] * 10, v[0], v[1], 0, 0, 0.1];
    expectCrossingNear(pair, quarticContact(...pair, 0, INF), "straight");
  });
});

describe("constructed far contacts (property)", () => {
  it("a contact built backwards from a known touching state is found, at an exact crossing, whenever the pair is evaluated", () => {
    const params = fcParams("far contact", 400);
    const unit = fc.double({ min: -1, max: 1, noNaN: true });
    fc.assert(
      fc.property(
        fc.integer({ min: 3, max: 11 }), // the path spans about 10^k contact distances
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }), // contact direction
        fc.double({ min: 0.2, max: 1, noNaN: true }), // approach: share of the speed along -e
        unit,
        unit,
        fc.double({ min: 0.1, max: 10, noNaN: true }), // contact distance R
        fc.double({ min: 0, max: 1, noNaN: true }),
        (k, angle, along, wxs, wys, R, frac) => {
          // At the contact time T: relative position e (|e| = R), velocity v approaching, constant w.
          const span = R * 10 ** k;
          const T = 10;
          const ex = R * Math.cos(angle);
          const ey = R * Math.sin(angle);
          const speed = span / T;
          const side = Math.sqrt(1 - along * along);
          const vx = speed * (-along * Math.cos(angle) - side * Math.sin(angle));
          const vy = speed * (-along * Math.sin(angle) + side * Math.cos(angle));
          const wx = (wxs * speed) / T;
          const wy = (wys * speed) / T;
          // Back to tau = 0: d = e - v T + w T^2 / 2, u = v - w T (rounded: the pair is near that).
          const pair: Pair = [
            ex - vx * T + 0.5 * wx * T * T,
            ey - vy * T + 0.5 * wy * T * T,
            vx - wx * T,
            vy - wy * T,
            wx,
            wy,
            R,
          ];
          const tau = quarticContact(...pair, 0, INF);
          const label = `k ${k}, T ${T}, tau ${tau}`;
          // Found no later than the constructed contact (an earlier one is a true first contact).
          expect(tau, label).toBeLessThanOrEqual(T * (1 + 1e-6));
          expectCrossingNear(pair, tau, label);
          // The same bits whenever the pair is (re)evaluated before the contact, or just after it.
          expect(quarticContact(...pair, frac * tau, INF), label).toBe(tau);
          expect(quarticContact(...pair, ulps(tau, 2), INF), label).toBe(tau);
        },
      ),
      params,
    );
  });
});
