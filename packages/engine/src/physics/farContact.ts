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
 * How: the near part of the window, where a cheap bound on |d(tau)| stays within FAR_CONTACT_REACH
 * contact distances, is solved as it stands (every pair of an ordinary scene stops here). The far part
 * is narrowed to where the pair can touch at all (farWindow.ts, closed form), then cut at the
 * extrema of the distance (the roots of f', a cubic whose roots are well conditioned:
 * they place a closest point within about UNIT_ROUNDOFF * M). A contact in the far part lies on a
 * piece where the distance decreases; the gap is re-expanded about that piece's closest point, where
 * its terms are of size R^2 again, and its crossing is solved there.
 */

import { realRootsInto } from "../roots/realRoots.js";
import { FAR_CONTACT_REACH } from "../tolerances.js";
import { farWindow } from "./farWindow.js";
import { firstDownCrossingQuartic } from "./quarticCrossing.js";

const INF = Number.POSITIVE_INFINITY;
const window = new Float64Array(2);
const slope = new Float64Array(4);
const local = new Float64Array(5);
const extrema: number[] = [];
const crossings: number[] = [];

/** First contact of the pair in [lo, hi] (see the header); d, u, w relative, R the contact distance. */
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
): number {
  const c0 = dx * dx + dy * dy - R * R;
  const c1 = 2 * (dx * ux + dy * uy);
  const c2 = ux * ux + uy * uy + (dx * wx + dy * wy);
  const c3 = ux * wx + uy * wy;
  const c4 = 0.25 * (wx * wx + wy * wy);
  const near = nearReach(dx, dy, ux, uy, wx, wy, FAR_CONTACT_REACH * R, hi);
  if (near >= hi) return firstDownCrossingQuartic(c0, c1, c2, c3, c4, lo, hi);
  if (lo <= near) {
    const t = firstDownCrossingQuartic(c0, c1, c2, c3, c4, lo, near);
    if (t !== INF) return t;
  }
  return farPart(dx, dy, ux, uy, wx, wy, R, c1, c2, c3, c4, lo, near, hi);
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

/**
 * The far part [near, hi], narrowed to where the pair can touch (farWindow.ts): the pieces between
 * consecutive extrema of the distance, in order; the first decreasing piece that reaches the contact
 * distance and does not end before lo holds the contact.
 */
function farPart(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  c1: number,
  c2: number,
  c3: number,
  c4: number,
  lo: number,
  near: number,
  hi: number,
): number {
  if (!farWindow(dx, dy, ux, uy, wx, wy, R, near, hi, window)) return INF;
  const from = window[0] as number;
  const to = window[1] as number;
  if (to < lo) return INF;
  slope[0] = c1;
  slope[1] = 2 * c2;
  slope[2] = 3 * c3;
  slope[3] = 4 * c4;
  realRootsInto(slope, from, to, extrema);
  const n = extrema.length;
  let p = from;
  for (let i = 0; i <= n; i++) {
    const q = i < n ? (extrema[i] as number) : to;
    if (q > p && q >= lo && q < INF && isDecreasing(p, q)) {
      const t = pieceContact(dx, dy, ux, uy, wx, wy, R, p, q, near);
      if (t !== INF) return t;
    }
    p = q;
  }
  return INF;
}

/** Whether the distance decreases on the piece (p, q) between two extrema: f' < 0 inside it. */
function isDecreasing(p: number, q: number): boolean {
  const m = 0.5 * (p + q);
  return (
    (slope[0] as number) +
      m * ((slope[1] as number) + m * ((slope[2] as number) + m * (slope[3] as number))) <
    0
  );
}

/**
 * The crossing of the contact distance on a piece [p, q] of decreasing distance, solved about the
 * closest point q: in s = q - tau the gap is g(s) = f(q - s), increasing on [0, q - p]. INF when the
 * distance at q is not below R (a graze or a miss).
 */
function pieceContact(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  p: number,
  q: number,
  near: number,
): number {
  const ex = dx + q * (ux + 0.5 * wx * q);
  const ey = dy + q * (uy + 0.5 * wy * q);
  const vx = ux + wx * q;
  const vy = uy + wy * q;
  const g0 = ex * ex + ey * ey - R * R;
  if (!(g0 < 0)) return INF;
  local[0] = g0;
  local[1] = -2 * (ex * vx + ey * vy);
  local[2] = vx * vx + vy * vy + (ex * wx + ey * wy);
  local[3] = -(vx * wx + vy * wy);
  local[4] = 0.25 * (wx * wx + wy * wy);
  realRootsInto(local, 0, q - p, crossings);
  const k = crossings.length;
  if (k > 0) return q - (crossings[k - 1] as number);
  // Within the contact distance over the whole piece: at its start p the pair is touching and
  // begins (or, at the near part's end, goes on) approaching.
  if (p === near && near > 0) {
    // The crossing lies in the near part (which the caller did not search when lo > near).
    const t = firstDownCrossingQuarticAt(dx, dy, ux, uy, wx, wy, R, near);
    if (t !== INF) return t;
  }
  return p;
}

/** The near part's crossing under way at its end `near` (the unmodified quartic, lo = hi = near). */
function firstDownCrossingQuarticAt(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  near: number,
): number {
  return firstDownCrossingQuartic(
    dx * dx + dy * dy - R * R,
    2 * (dx * ux + dy * uy),
    ux * ux + uy * uy + (dx * wx + dy * wy),
    ux * wx + uy * wy,
    0.25 * (wx * wx + wy * wy),
    near,
    near,
  );
}
