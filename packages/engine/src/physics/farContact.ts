/**
 * Contact of an accelerated pair (friction or gravity): the quartic gap f(tau) = |d(tau)|^2 - R^2
 * with d(tau) = d + u tau + w tau^2 / 2, solved so that a far contact is not lost to rounding (pure;
 * no allocation). Same contract as every function in timeOfImpact.ts: the first downward crossing in
 * [lo, hi], a contact under way at lo reported as the crossing that led to it, and a result that is a
 * function of the motions alone (every split point below depends on d, u, w, R and hi, never on lo).
 *
 * Why: f's terms have the size M^2 of the path's span M, and cancel to R^2 at a contact, so its
 * rounding error is about UNIT_ROUNDOFF * M^2. Once M is ~1e8 R that is more than R^2 and a contact
 * vanishes (a disc dropped from 1e8 radii onto a point fell through it).
 *
 * How:
 * 1. The times at which the pair can touch at all: at most two windows in which it is within 2R in
 *    both components (farWindow.ts, closed form). A pair with none needs no solve; most pairs, near
 *    or far, end here.
 * 2. The near part of [0, hi], where a cheap bound on |d(tau)| stays within FAR_CONTACT_REACH contact
 *    distances, is solved as it stands (every pair of an ordinary scene stops here). When a window
 *    straddles the end of the near part, the near part runs on to that window's end, so the split
 *    never falls inside a contact (review: evaluated a few ulps before a contact at the split, the
 *    near part saw the gap <= 0 but not the crossing past its end).
 * 3. Each later window: the gap re-expanded about the window's start, where its terms are of size
 *    R^2 again, and solved there.
 * Positions of size M carry a rounding error of about UNIT_ROUNDOFF * M, so that is the accuracy of
 * a far contact's place.
 */

import { APPROACH_NOISE, FAR_CONTACT_REACH, RESPONSE_ULP } from "../tolerances.js";
import { farWindows } from "./farWindow.js";
import { firstDownCrossingQuartic } from "./quarticCrossing.js";

const INF = Number.POSITIVE_INFINITY;
const INF_NEG = Number.NEGATIVE_INFINITY;
const windows = new Float64Array(4);

/**
 * First contact of the pair in [lo, hi] (see the header); d, u, w relative, R the contact distance.
 * `dvScale` and `dwScale` are the sizes of d.v and d.w from the two bodies' own velocities and
 * accelerations (of d.u and d.w by default; see discDiscTimeScaled): u and w are differences, so
 * their rounding is relative to the bodies' own, not to u and w. `band`: the rounding of the gap
 * f = |d|^2 - R^2 within which a pressed pair that cannot leave it is a resting contact (see
 * firstDownCrossingQuartic; -Infinity: no such test).
 */
export function quarticContact(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  lo: number,
  hi: number,
  dvScale = Math.abs(dx * ux) + Math.abs(dy * uy),
  dwScale = Math.abs(dx * wx) + Math.abs(dy * wy),
  band = INF_NEG,
): number {
  const c0 = dx * dx + dy * dy - R * R;
  const c1 = 2 * (dx * ux + dy * uy);
  const c2 = ux * ux + uy * uy + (dx * wx + dy * wy);
  const c3 = ux * wx + uy * wy;
  const c4 = 0.25 * (wx * wx + wy * wy);
  // Where the pair can touch at all (closed form): most pairs never come within 2R and need no solve.
  const n = farWindows(dx, dy, ux, uy, wx, wy, R, 0, hi, windows);
  if (n === 0) return INF;
  let near = nearReach(dx, dy, ux, uy, wx, wy, FAR_CONTACT_REACH * R, hi);
  // Rounding of the gap's rate at lo (APPROACH_NOISE): a touching pair approaching by less grazes.
  const l = Math.max(lo, 0);
  const uu = ux * ux + uy * uy;
  const uw = Math.abs(ux * wx) + Math.abs(uy * wy);
  const noise =
    APPROACH_NOISE *
      (2 * (Math.abs(dx * ux) + Math.abs(dy * uy)) + l * (2 * (uu + dwScale) + l * (3 * uw + l * 4 * c4))) +
    2 * RESPONSE_ULP * (dvScale + l * dwScale);
  // Rounding of f''(lo), the accelerations' directions included: the pair is pressed together only
  // beyond it (friction on two discs sliding past each other along the contact).
  const pressNoise = APPROACH_NOISE * (2 * (uu + dwScale) + l * (6 * uw + l * 12 * c4));
  if (near >= hi) return firstDownCrossingQuartic(c0, c1, c2, c3, c4, lo, hi, noise, pressNoise, band);
  let i = 0;
  while (i < n && (windows[2 * i + 1] as number) < near) i++; // wholly in the near part
  if (i < n && (windows[2 * i] as number) <= near) {
    // The pair may be within reach of a contact where the near part ends: the near part runs on to
    // that window's end, where the pair is at least 2R apart in one component, so that no crossing
    // (and no contact under way) straddles the split and lo cannot see one side of it only.
    near = windows[2 * i + 1] as number;
    i++;
  }
  if (lo <= near) {
    const t = firstDownCrossingQuartic(c0, c1, c2, c3, c4, lo, near, noise, pressNoise, band);
    if (t !== INF) return t;
  }
  // The far windows, in order: the gap re-expanded about the window's start a, where its terms are
  // of size R^2 again, and solved in local time [max(lo - a, 0), b - a].
  for (; i < n; i++) {
    const a = windows[2 * i] as number;
    const b = windows[2 * i + 1] as number;
    if (b < lo) continue;
    const ex = dx + a * (ux + 0.5 * wx * a);
    const ey = dy + a * (uy + 0.5 * wy * a);
    const vx = ux + wx * a;
    const vy = uy + wy * a;
    const t = firstDownCrossingQuartic(
      ex * ex + ey * ey - R * R,
      2 * (ex * vx + ey * vy),
      vx * vx + vy * vy + (ex * wx + ey * wy),
      vx * wx + vy * wy,
      c4,
      Math.max(lo - a, 0),
      b - a,
    );
    if (t !== INF) return a + t;
  }
  return INF;
}

/**
 * The first tau at which the bound |d| + |u| tau + |w| tau^2 / 2 (in the 1-norm, which is at least
 * the Euclidean one, so the bound is conservative) reaches `reach`; hi when it stays below it up to
 * hi, 0 when the pair starts beyond it.
 */
function nearReach(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  reach: number,
  hi: number,
): number {
  const D = Math.abs(dx) + Math.abs(dy);
  const U = Math.abs(ux) + Math.abs(uy);
  const W = Math.abs(wx) + Math.abs(wy);
  if (D >= reach) return 0;
  if (hi < INF && D + hi * (U + 0.5 * W * hi) <= reach) return hi;
  const slack = reach - D;
  // Positive root of (W/2) t^2 + U t - slack, in the form without cancellation.
  return (2 * slack) / (U + Math.sqrt(U * U + 2 * W * slack));
}
