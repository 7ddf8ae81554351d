/**
 * Time of impact (pure functions of numbers; no allocation on the hot path).
 *
 * Every function works in local time tau measured from a base time at which both motions are given,
 * and looks for the first contact in the window [lo, hi] (lo >= 0). A contact counts only while the
 * pair approaches: the gap function crosses zero downwards, or the pair already touches (gap <= 0) and
 * approaches at lo (Newton's cradle, round-off overlaps). A touching pair that separates never
 * collides. Each function returns the contact time tau, or +Infinity when there is none in the window.
 *
 * A contact already under way at lo returns the downward root that led to it, even when that root
 * lies before lo by a rounding error, and lo only when there is no such root (the pair started
 * touching). The caller clamps base + tau to the current time. So the time found for a pair is a
 * function of the two motions alone, not of the moment it is evaluated: a pair evaluated just after
 * its rounded contact time (a stale prediction popped there, a World rebuilt from a keyframe, the
 * grid bringing the pair together later) gives the same bits as one evaluated long before.
 *
 * Gap functions:
 *   disc–disc / disc–point:  f(tau) = |d + u tau + w tau^2 / 2|^2 - R^2   (degree <= 4; 2 when w = 0)
 *   disc–line:               h(tau) = ±s(tau) - r, s the signed distance to the line (degree <= 2)
 * Their crossings are solved in quadraticCrossing.ts (degree 2), quarticCrossing.ts (degree 4) and
 * farContact.ts (degree 4, a far approach re-anchored at its closest point).
 */

import { APPROACH_NOISE, CONTACT_BAND, NEGLIGIBLE_DRIFT, RESPONSE_ULP } from "../tolerances.js";
import { quarticContact } from "./farContact.js";
import { firstDownCrossingQuadratic } from "./quadraticCrossing.js";
import { firstDownCrossingQuartic } from "./quarticCrossing.js";

/**
 * First approach root of the gap polynomial of two discs (or a disc and a point, with the point's
 * motion zero): d, u, w are the relative position, velocity and acceleration (other minus this) at
 * the base time, R the contact distance. `dvScale` and `dwScale` are the sizes of d.v and d.w from
 * the two bodies' own velocities and accelerations, |dx| (|vx1| + |vx2|) + |dy| (|vy1| + |vy2|) and
 * the same with a (of d.u and d.w by default): see discDiscTimeScaled.
 */
export function discDiscTime(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  lo: number,
  hi: number,
  quadraticFastPath = true,
  dvScale = Math.abs(dx * ux) + Math.abs(dy * uy),
  dwScale = Math.abs(dx * wx) + Math.abs(dy * wy),
): number {
  return discDiscTimeScaled(
    dx,
    dy,
    ux,
    uy,
    wx,
    wy,
    R,
    lo,
    hi,
    quadraticFastPath,
    dvScale,
    dwScale,
    Number.NEGATIVE_INFINITY,
  );
}

/**
 * discDiscTime with every argument given (the hot path: no defaults, small enough to inline).
 * u and w are differences of the two bodies' velocities and accelerations, so their rounding is
 * relative to those, not to u and w: two discs sliding side by side under friction have a u and a
 * w that are pure rounding, and what the response can change in their velocities along the line of
 * centres is relative to the velocities' components too (APPROACH_NOISE, RESPONSE_ULP). Hence
 * `dvScale` = |dx| (|vx1| + |vx2|) + |dy| (|vy1| + |vy2|) and `dwScale` the same with the
 * accelerations, each body's part added first so that both orders of a pair give the same bits.
 * `band`: for a disc against a point, the gap's rounding within which a pressed contact that cannot
 * leave it is resting (quarticContact); -Infinity for two discs, whose contacts never rest.
 */
export function discDiscTimeScaled(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  lo: number,
  hi: number,
  quadraticFastPath: boolean,
  dvScale: number,
  dwScale: number,
  band: number,
): number {
  // A relative acceleration that cannot move the pair by NEGLIGIBLE_DRIFT of the contact distance
  // before either motion ends is dropped (w tau^2 / 2 bounded in the 1-norm): the straight path
  // makes the same contacts up to that rounding, and its rate is the whole story at a touching
  // contact. Kept, a rounding-level press in the last nanoseconds before two discs stop made a
  // contact a fraction of an ulp of time after now that the response, at now, saw no approach in,
  // for ever (a 20 x 20 rack broken under friction).
  if ((wx === 0 && wy === 0) || 0.5 * (Math.abs(wx) + Math.abs(wy)) * hi * hi <= NEGLIGIBLE_DRIFT * R) {
    const uu = ux * ux + uy * uy;
    if (uu === 0) return Number.POSITIVE_INFINITY;
    const c0 = dx * dx + dy * dy - R * R;
    const c1 = 2 * (dx * ux + dy * uy);
    // c1^2 - 4 uu c0 = 4 (uu R^2 - (d x u)^2) (Lagrange's identity), free of the cancellation of
    // two terms of size |d|^2 |u|^2 that loses every digit once the gap is ~1e8 contact distances.
    const cross = dx * uy - dy * ux;
    const discriminant = 4 * (uu * R * R - cross * cross);
    // A pair that misses (no real root) and is apart at lo never touches: the solver's answer
    // (firstDownCrossingQuadratic), given here without its call, as most approaching pairs of a gas miss.
    if (quadraticFastPath && discriminant < 0 && c0 + lo * (c1 + lo * uu) > 0)
      return Number.POSITIVE_INFINITY;
    // An approach within the rounding of c1 = 2 d.u (APPROACH_NOISE), or too slow for the response
    // to change the velocities (RESPONSE_ULP), is a graze.
    const noise = APPROACH_NOISE * 2 * (Math.abs(dx * ux) + Math.abs(dy * uy)) + 2 * RESPONSE_ULP * dvScale;
    if (!quadraticFastPath) {
      // The benchmark's ablation: the same gap solved as a general quartic, as before the fast path.
      return firstDownCrossingQuartic(c0, c1, uu, 0, 0, lo, hi, noise);
    }
    return firstDownCrossingQuadratic(c0, c1, uu, lo, hi, true, discriminant, noise, 0);
  }
  return quarticContact(dx, dy, ux, uy, wx, wy, R, lo, hi, dvScale, dwScale, band);
}

/**
 * First contact of a disc (radius r) with the infinite line through (x1, y1) with unit normal
 * (nx, ny), from either side: s(tau) = n.(p - P1) with p = p0 + v tau + a tau^2 / 2.
 * `side` receives +1 when the disc hits the positive side, -1 the negative side.
 */
export function discLineCrossings(
  px: number,
  py: number,
  vx: number,
  vy: number,
  ax: number,
  ay: number,
  x1: number,
  y1: number,
  nx: number,
  ny: number,
  r: number,
  lo: number,
  hi: number,
  out: Float64Array,
): void {
  const s0 = nx * (px - x1) + ny * (py - y1);
  const s1 = nx * vx + ny * vy;
  const s2 = 0.5 * (nx * ax + ny * ay);
  // Positive side: h+ = s - r; negative side: h- = -s - r. Only the side the centre is on now can
  // be in contact now; the other side can only be reached later (around the end of a segment).
  const positive = s0 + lo * (s1 + lo * s2) >= 0;
  // Rounding of h'(lo) = s1 + 2 s2 lo: an approach below it is a graze (see APPROACH_NOISE).
  const noise =
    APPROACH_NOISE * (Math.abs(nx * vx) + Math.abs(ny * vy) + lo * (Math.abs(nx * ax) + Math.abs(ny * ay)));
  // Rounding of h'' = 2 s2, the acceleration's direction included (friction along the line).
  const pressNoise = APPROACH_NOISE * (Math.abs(ax) + Math.abs(ay));
  // Rounding of the gap h = ±s - r: a contact that stays within it never opens (CONTACT_BAND).
  // (The coordinates weighted by the normal's components: along a horizontal floor x does not enter
  // the gap, and a floor anchored at x = 1e6 refused a disc bouncing 1e-9 above it: review.)
  const band =
    CONTACT_BAND *
    (Math.abs(nx) * (Math.abs(px) + Math.abs(x1)) +
      Math.abs(ny) * (Math.abs(py) + Math.abs(y1)) +
      r +
      lo * (Math.abs(s1) + lo * Math.abs(s2)));
  out[0] = firstDownCrossingQuadratic(s0 - r, s1, s2, lo, hi, positive, Number.NaN, noise, pressNoise, band);
  out[1] = firstDownCrossingQuadratic(
    -s0 - r,
    -s1,
    -s2,
    lo,
    hi,
    !positive,
    Number.NaN,
    noise,
    pressNoise,
    band,
  );
}
