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
 */

import { APPROACH_NOISE, CONTACT_BAND, NEGLIGIBLE_DRIFT, RESPONSE_ULP } from "../tolerances.js";
import { quarticContact } from "./farContact.js";
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
 * First tau in [lo, hi] where h(tau) = c0 + c1 tau + c2 tau^2 crosses zero downwards. When h(lo) <= 0
 * and h is decreasing there (or resting with h'' < 0) and `immediate` is true, the contact is under
 * way: its downward root (at or before lo up to rounding; the caller clamps), or lo when h has no
 * root. Roots use the cancellation-free closed form; `discriminant`, when given, is c1^2 - 4 c2 c0
 * computed by the caller in a form that does not cancel. A touching pair whose h'(lo) is negative
 * by no more than `noise` (the rounding of h' the caller bounds) does not count as approaching,
 * unless an acceleration presses it in (c2 < 0): its response could not tell that approach from
 * none, and the same contact would be found again at once for ever (a Zeno state in no time).
 * Likewise an acceleration presses it in only when h'' < -`pressNoise` (the rounding of c2, inputs
 * included, which the caller bounds): below that the press is the rounding of an acceleration along
 * the contact (friction on a disc sliding past another or along a line).
 */
export function firstDownCrossingQuadratic(
  c0: number,
  c1: number,
  c2: number,
  lo: number,
  hi: number,
  immediate = true,
  discriminant = Number.NaN,
  noise = 0,
  pressNoise = 0,
  band = Number.NEGATIVE_INFINITY,
): number {
  const a = DOWN_ARGS;
  a[0] = c0;
  a[1] = c1;
  a[2] = c2;
  a[3] = lo;
  a[4] = hi;
  a[5] = discriminant;
  a[6] = noise;
  a[7] = pressNoise;
  a[9] = band;
  downCrossing(immediate);
  return a[8] as number;
}

/**
 * The doubles of `downCrossing`: c0, c1, c2, lo, hi, discriminant, noise, pressNoise in, the result
 * at [8], band in at [9]. The solver is too large for V8 to inline into its hot callers (pair tests, cell exits),
 * and a double passed to or returned from a call that is not inlined is boxed: a heap allocation
 * each, about 40 per collision in a gas. Through this array they cross the call unboxed, and the
 * small wrapper above, which V8 does inline, keeps the pure signature.
 */
const DOWN_ARGS = new Float64Array(10);

/** firstDownCrossingQuadratic on DOWN_ARGS. */
function downCrossing(immediate: boolean): void {
  const a = DOWN_ARGS;
  const c0 = a[0] as number;
  const c1 = a[1] as number;
  const c2 = a[2] as number;
  const lo = a[3] as number;
  const hi = a[4] as number;
  const noise = a[6] as number;
  a[8] = Number.POSITIVE_INFINITY;
  if (!(lo <= hi)) return;
  const hLo = c0 + lo * (c1 + lo * c2);
  const dLo = c1 + 2 * c2 * lo;
  // Touching and approaching (or resting under an acceleration into the contact) at lo.
  if (hLo <= 0 && immediate && (dLo < -noise || (dLo <= 0 && c2 < -(a[7] as number)))) {
    a[8] = quadraticUnderWay(c0, c1, c2, lo, hi, a[5] as number);
    return;
  }
  // Touching and approaching by no more than the noise, with nothing pressing it in: a graze.
  if (hLo <= 0 && immediate && dLo <= 0) return;
  // Touching (within the band: a rounding above, or inside) and at rest or moving away, but turned
  // back for good (approaching at hi: not a friction stop) before the gap leaves the band: the
  // contact never opens, a resting contact (CONTACT_BAND). The contact is now (at the motion's
  // start, where it is first seen), and the response refuses it.
  const band = a[9] as number;
  if (
    immediate &&
    hLo <= band &&
    c2 < -(a[7] as number) &&
    hLo - (dLo * dLo) / (4 * c2) <= band &&
    c1 + 2 * c2 * hi < -noise
  ) {
    a[8] = lo;
    return;
  }
  // Convex and not decreasing at lo: it never comes down again (the common, cheap rejection).
  if (c2 >= 0 && dLo >= 0) return;
  if (c2 === 0) {
    const r = -c0 / c1;
    if (r >= lo && r <= hi) a[8] = r;
    return;
  }
  const given = a[5] as number;
  const disc = Number.isNaN(given) ? c1 * c1 - 4 * c2 * c0 : given;
  if (disc < 0) return;
  const sq = Math.sqrt(disc);
  const q = c1 >= 0 ? -0.5 * (c1 + sq) : -0.5 * (c1 - sq);
  if (q === 0) return; // c0 = c1 = 0: touching with zero slope, handled above
  let r1 = q / c2;
  let r2 = c0 / q;
  if (r1 > r2) {
    const t = r1;
    r1 = r2;
    r2 = t;
  }
  // The derivative at a root of a quadratic is +-sqrt(disc): it is negative at the smaller root
  // when c2 > 0 and at the larger root when c2 < 0.
  const down = c2 > 0 ? r1 : r2;
  if (down < lo) {
    // Past the crossing already: a round-off overlap. Approaching now means the contact is under
    // way since the crossing (the caller clamps it to now).
    if (dLo < -noise && immediate) a[8] = down;
    return;
  }
  if (disc === 0) return; // tangency without crossing: a graze, no impulse
  if (down <= hi) a[8] = down;
}

/**
 * A contact under way at lo (h(lo) <= 0, approaching): the downward root of h, at or before lo up
 * to rounding (there is only one), or lo when h has none (it started touching).
 */
function quadraticUnderWay(
  c0: number,
  c1: number,
  c2: number,
  lo: number,
  hi: number,
  discriminant: number,
): number {
  if (c2 === 0) {
    const r = -c0 / c1; // c1 < 0 here
    return r <= hi ? r : lo;
  }
  const disc = Number.isNaN(discriminant) ? c1 * c1 - 4 * c2 * c0 : discriminant;
  if (disc < 0) return lo;
  const sq = Math.sqrt(disc);
  const q = c1 >= 0 ? -0.5 * (c1 + sq) : -0.5 * (c1 - sq);
  if (q === 0) return lo;
  const r1 = q / c2;
  const r2 = c0 / q;
  const down = c2 > 0 ? Math.min(r1, r2) : Math.max(r1, r2);
  return down <= hi ? down : lo;
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
