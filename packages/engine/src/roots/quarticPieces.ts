/**
 * The roots of the quartic hot path on certified monotone pieces (registers: quarticRegisters.ts):
 * each bracket with exact signs of opposite signs at its ends holds exactly one root, found by
 * Halley (quarticHalley.ts) and certified to 1 ulp (quarticRefine.ts), then appended to `found`.
 *
 * - `unimodal(s0, zeroAtLo)`: p has exactly one critical point in [lo, lo + h] and the exact sign
 *   s0 at lo, or just after lo when p(lo) = 0 (zeroAtLo), and at lo + h; BC[0] = p(lo); H[4] a
 *   start. An estimate xs of the critical point x* by safeguarded Halley on p′ over [lo, hi]
 *   (when p′ changes sign there), then the exact sign of p at xs (plain Horner with its bound):
 *   p is monotone on [lo, x*] and [x*, lo + h], so p of the other sign at xs means one root in
 *   (lo, xs) and one in (xs, hi) when p(hi) has the sign s0 again; p of the sign s0 at xs means
 *   no root only once keepsSign certifies that sign at x* itself (Halley stops early: at a flat
 *   extremum xs can miss a dip of p between xs and x*). Returns 1 when done; 0 when p′(lo),
 *   p′(hi) do not change sign or p dips after a zero at lo (the caller subdivides instead); −1
 *   when p(xs) is at rounding-noise level, keepsSign cannot certify, or p(hi) = 0 (the general
 *   path, with its exact repair around noisy critical points, decides) or a bracket's ends round
 *   together.
 * - `solveOnes(nOnes, zeroAtLo)`: one certified root per one-root piece of quarticIsolate.ts. A
 *   piece's real ends lo + s·h are replaced by the nearest doubles, whose exact signs must match
 *   the certified signs at the real ends (so no root lies between a double and its real end).
 *   False on any doubt (a differing sign, an exact zero, ends that round together).
 */

import { PLAIN_HORNER_BOUND_FACTOR, UNIT_ROUNDOFF } from "../tolerances.js";
import { halley } from "./quarticHalley.js";
import { ones } from "./quarticIsolate.js";
import { refined } from "./quarticRefine.js";
import * as reg from "./quarticRegisters.js";
import { signAt, signPlain } from "./quarticSigns.js";

/** Module-local copies (V8 folds a module's own consts, not imports; see quarticRegisters.ts). */
const Q = reg.Q;
const H = reg.H;
const BC = reg.BC;
const absAt = reg.absAt;
const P1 = reg.P1;
const pieces = ones;
/** Plain Horner error bound of p and of p′ (degree 3, with 3·c3 rounded), as quarticSigns.ts. */
export const B4 = PLAIN_HORNER_BOUND_FACTOR * 4 * UNIT_ROUNDOFF;
/** As quarticSigns.ts: below this Σ|cᵢ||x|ⁱ the plain bound needs underflow slack (not taken).
 *  (A copy; constantCopies.test.ts checks it and B4 against quarticSigns.ts's.) */
export const TINY_SCALE = 2 ** -600;
/** Covers the rounding of the (nonnegative) bound terms of keepsSign, ≤ 10u relative. */
const SAFE = 1 + 2 ** -20;
/** After an exact zero at lo, a one-root piece [lo, b] is bracketed from lo + (b − lo)·ZERO_OFFSET. */
const ZERO_OFFSET = 2 ** -10;

/**
 * The root in (a, b), where p's exact signs are sa at a and −sa at b and |p| is fa, fb: Halley
 * (values sa·fa and −sa·fb, or ±1 where |p| underflowed to 0; the start guess when inside, else
 * from the critical ends: 1 = a, 2 = b, see quarticHalley.ts), then refined and appended to
 * `found`. False when a and b round together.
 */
function rootIn(
  a: number,
  b: number,
  sa: number,
  fa: number,
  fb: number,
  guess: number,
  critical: number,
): boolean {
  if (!(a < b)) return false;
  H[0] = a;
  H[1] = b;
  H[2] = sa * (fa > 0 ? fa : 1);
  H[3] = -sa * (fb > 0 ? fb : 1);
  H[4] = guess;
  halley(0, critical);
  H[0] = a;
  H[1] = b;
  H[2] = fa;
  H[3] = fb;
  H[4] = H[5] as number;
  reg.pushRoot(refined(sa));
  return true;
}

/**
 * Certifies that p has the exact sign s0 at its only critical point x* in [lo, lo + h], given
 * Halley's approximation xs = H[5] (stopped early: far from x* where p″ is small), where plain Horner
 * found the sign s0 with |p(xs)| = absAt[0]. On the real interval I = [xs − w, xs + w] inside
 * [lo, hi], w = twice Newton's step (a rigorous bound of |p′(xs)| over |p″(xs)|):
 * - |p″| ≥ m > 0 on I (p″(xs) less its bound and max|p‴|·w), so p′ is strictly monotone there and
 *   has a root within |p′(xs)|/m of xs; inside I when that is < w: it is x*, p′'s only root in
 *   [lo, lo + h];
 * - |p(x) − p(xs)| ≤ |p′(xs)|·w + max|p″|/2·w² on I (max|p″|/2 ≤ Σ C(i,2)|cᵢ|(|xs| + w)^(i−2));
 *   |p(xs)| beyond its plain error bound by more keeps the sign s0 over I, so at x*.
 * The bounds use the plain Horner bound B4 for p, p′, p″ (3c3, 6c3, 12c4 rounded: ≤ 7u in all);
 * SAFE covers the rounding of the nonnegative bound terms. False on any doubt. Cost: 528 of the
 * benchmark's 4000 collision quartics reach it, +20 instructions per call on average (perf stat).
 */
function keepsSign(): boolean {
  const xs = H[5] as number;
  const c0 = Q[0] as number;
  const c1 = Q[1] as number;
  const c2 = Q[2] as number;
  const c3 = Q[3] as number;
  const c4 = Q[4] as number;
  const lo = Q[5] as number;
  const hi = Q[6] as number;
  const ac1 = Math.abs(c1);
  const ac2 = Math.abs(c2);
  const ac3 = Math.abs(c3);
  const ac4 = Math.abs(c4);
  const ax = Math.abs(xs);
  // |p(xs)| (signPlain's), the sums Σ|cᵢ||x|ⁱ of p, p′, p″ (their plain Horner error bounds).
  const av = (((ac4 * ax + ac3) * ax + ac2) * ax + ac1) * ax + Math.abs(c0);
  const d = ((4 * c4 * xs + 3 * c3) * xs + 2 * c2) * xs + c1;
  const ad = ((4 * ac4 * ax + 3 * ac3) * ax + 2 * ac2) * ax + ac1;
  const dd = (12 * c4 * xs + 6 * c3) * xs + 2 * c2;
  const add = (12 * ac4 * ax + 6 * ac3) * ax + 2 * ac2;
  if (!(av >= TINY_SCALE && ad >= TINY_SCALE && add >= TINY_SCALE)) return false;
  const dMax = Math.abs(d) + B4 * ad;
  const w = (2 * dMax) / Math.abs(dd);
  // The real bracket [xs − w, xs + w] inside [lo, hi]: rounding is monotone, so a computed end
  // strictly inside [lo, hi] has its exact value inside. (False also for NaN, infinite w: dd = 0.)
  if (!(xs - w > lo && xs + w < hi)) return false;
  const X = ax + w;
  const m = Math.abs(dd) - (B4 * add + (24 * ac4 * X + 6 * ac3) * w) * SAFE;
  if (!(dMax * SAFE < m * w)) return false;
  const drift = (dMax + ((6 * ac4 * X + 3 * ac3) * X + ac2) * w) * w;
  return (absAt[0] as number) > (B4 * av + drift) * SAFE;
}

export function unimodal(s0: number, zeroAtLo: boolean): number {
  const c1 = Q[1] as number;
  const c2 = Q[2] as number;
  const c3 = Q[3] as number;
  const c4 = Q[4] as number;
  const lo = Q[5] as number;
  const hi = Q[6] as number;
  const q1 = 2 * c2;
  const q2 = 3 * c3;
  const q3 = 4 * c4;
  const fa = ((q3 * lo + q2) * lo + q1) * lo + c1;
  const fb = ((q3 * hi + q2) * hi + q1) * hi + c1;
  if (fa === 0 || fb === 0 || fa < 0 === fb < 0) return 0;
  Q[P1] = c1;
  Q[P1 + 1] = q1;
  Q[P1 + 2] = q2;
  Q[P1 + 3] = q3;
  Q[P1 + 4] = 0;
  H[0] = lo;
  H[1] = hi;
  H[2] = fa;
  H[3] = fb;
  halley(P1, 0);
  const xs = H[5] as number;
  const sx = signPlain(xs, 0);
  if (sx === 0) return -1;
  // p keeps the sign s0 at its only extremum: no root (p(lo + h) has the sign s0 too, and p is
  // monotone from x* to there, so p(hi) has it).
  if (sx === s0) return keepsSign() ? 1 : -1;
  if (zeroAtLo) return 0; // p(lo) = 0 and a dip: subdivision brackets the roots after lo
  const ax = absAt[0] as number;
  const sh = signAt(hi, 1);
  if (sh === 0) return -1;
  const ah = absAt[1] as number;
  // One root in (lo, x*), and one in (x*, hi) unless it lies beyond hi.
  if (!rootIn(lo, xs, s0, Math.abs(BC[0] as number), ax, Number.NaN, 2)) return -1;
  if (sh !== sx && !rootIn(xs, hi, sx, ax, ah, Number.NaN, 1)) return -1;
  return 1;
}

export function solveOnes(nOnes: number, zeroAtLo: boolean): boolean {
  const lo = Q[5] as number;
  const hi = Q[6] as number;
  const h = Q[7] as number;
  for (let k = 0; k < nOnes; k++) {
    const o = 4 * k;
    const sl = pieces[o] as number;
    const sr = pieces[o + 1] as number;
    const sg = pieces[o + 3] as number;
    const last = sr === 1; // the piece reaching lo + h > hi
    let a = sl === 0 ? lo : lo + sl * h;
    if (a > hi) a = hi;
    const b = last ? hi : lo + sr * h;
    // p(lo) = 0 exactly: the piece's root is inside; start the bracket a little after lo, where p
    // must already have the sign just after lo (else the root is right there: general path).
    if (sl === 0 && zeroAtLo) a = lo + (b - lo) * ZERO_OFFSET;
    if (!(a < b) || b > hi) {
      // A last piece starting at hi (rounded): its root lies beyond hi iff p(hi) keeps its sign.
      if (last && a === hi && signAt(hi, 0) === sg) continue;
      return false;
    }
    if (signAt(a, 0) !== sg) return false;
    const sb = signAt(b, 1);
    if (sb === 0) return false;
    if (sb === sg) {
      if (last) continue; // the last piece's root lies beyond hi
      return false;
    }
    rootIn(a, b, sg, absAt[0] as number, absAt[1] as number, lo + (pieces[o + 2] as number) * h, 0);
  }
  return true;
}
