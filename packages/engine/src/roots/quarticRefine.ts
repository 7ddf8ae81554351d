/**
 * Certified refinement of a bracketed root of the quartic hot path (registers: quarticRegisters.ts):
 * certify.ts's refineRoot in scalar arithmetic, for the common case.
 *
 * `refined(sa)`: the root in the bracket H[0..1] = a < b, where p's exact signs are sa at a and −sa
 * at b, H[2..3] = |p| there, H[4] = the start x0 (Halley's result, inside): one compensated Horner
 * evaluation at x0 (as compHorner.ts: value, rigorous bound, p′(x0), p̃′(|x0|), p̃″(|x0|)/2) decides
 * its exact sign; then the certified local model p(x0 + h) ∈ p(x0) + p′(x0)·h ± (…) of refineRoot
 * decides the ulp around the compensated Newton root in one step, else walks ulp by ulp to two
 * adjacent doubles; the end with the smaller |p| is returned (within 1 ulp of an exact root).
 * When the compensated sign is uncertain, underflow is near or the model cannot decide, refineRoot
 * finishes from the narrowed bracket with full evaluations (exact fallback included).
 */

import {
  COMP_HORNER_BOUND_FACTOR,
  PLAIN_HORNER_BOUND_FACTOR,
  ROOTS_HOT_MODEL_SPAN,
  UNIT_ROUNDOFF,
} from "../tolerances.js";
import { MODEL_MIN_X, MODEL_SAFETY, refineRoot } from "./certify.js";
import { nextDown, nextUp } from "./nextDouble.js";
import * as reg from "./quarticRegisters.js";

/** Module-local copies (V8 folds a module's own consts, not imports; see quarticRegisters.ts). */
const Q = reg.Q;
const H = reg.H;
const U = UNIT_ROUNDOFF;
const B4 = PLAIN_HORNER_BOUND_FACTOR * 4 * U;
const COMP = COMP_HORNER_BOUND_FACTOR;
const SPAN = ROOTS_HOT_MODEL_SPAN;
const MIN_X = MODEL_MIN_X;
const SAFETY = MODEL_SAFETY;
/** compHorner.ts's constants: Dekker's split, underflow limits (see there). Copies, written out for
 *  the hot path; constantCopies.test.ts checks that they equal compHorner.ts's. */
export const SPLIT = 134217729;
export const UNDERFLOW = 2 ** -968;
export const SLACK_FREE = 2 ** -900;
export const TINY = 2 ** -1070;

export function refined(sa: number): number {
  if (refine(sa)) return H[5] as number;
  reg.ensureLoaded();
  return refineRoot(H[0] as number, H[1] as number, sa, H[2] as number, H[3] as number, H[4] as number);
}

/**
 * The scalar part of refined: true with the root in H[5]; false with the (narrowed) bracket, its
 * |p| and a start for refineRoot in H[0..4].
 */
function refine(sa: number): boolean {
  let a = H[0] as number;
  let b = H[1] as number;
  let absA = H[2] as number;
  let absB = H[3] as number;
  // Error bounds of absA, absB (the bracket's own |p| values carry none we know of).
  let errA = Number.POSITIVE_INFINITY;
  let errB = Number.POSITIVE_INFINITY;
  const x = H[4] as number;
  if (!(x > a && x < b)) return false;
  // Compensated Horner (compHorner.ts, degree 4): s + r the value, e the sum of the |error terms|,
  // noUnderflow every |product| ≥ UNDERFLOW, d = p′, a1 = p̃′, a2 = p̃″/2, aa = p̃. The first
  // round's updates of d, a1, a2, r and e from zero are exact (d = c4, a1 = |c4|, …).
  let t = SPLIT * x;
  const xh = t - (t - x);
  const xl = x - xh;
  const ax = Math.abs(x);
  // biome-ignore lint/complexity/useMathMinMax: Math.max compiles to data-dependent branches in V8
  const xm = ax > 1 ? ax : 1;
  let s = Q[4] as number;
  let aa = Math.abs(s);
  let d = 0;
  let a2 = 0;
  let a1 = 0;
  let r = 0;
  let e = 0;
  let noUnderflow = true; // every |product| ≥ UNDERFLOW (false for NaN)
  for (let k = 3; k >= 0; k--) {
    const ck = Q[k] as number;
    d = d * x + s;
    a2 = a2 * ax + a1;
    a1 = a1 * ax + aa;
    const p = s * x;
    t = SPLIT * s;
    const sh = t - (t - s);
    const sl = s - sh;
    const pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
    s = p + ck;
    const z = s - p;
    const q = pe + (p - (s - z) + (ck - z));
    r = r * x + q;
    e += Math.abs(q);
    noUnderflow = noUnderflow && Math.abs(p) >= UNDERFLOW;
    aa = aa * ax + Math.abs(ck);
  }
  const v = s + r;
  const av = Math.abs(v);
  const xm2 = xm * xm;
  const pw = xm2 * xm2;
  let bound = 0;
  if (e !== 0 || !noUnderflow) {
    bound = COMP * (U * av + 16 * U * U * aa);
    if (!(aa >= pw * SLACK_FREE)) bound += TINY * 5 * pw;
  }
  if (!(av > bound || bound === 0)) return false; // uncertain: refineRoot decides exactly
  const sx = v > 0 ? 1 : v < 0 ? -1 : 0;
  if (sx === 0) {
    H[5] = x;
    return true;
  }
  if (sx === sa) {
    a = x;
    absA = av;
    errA = bound;
  } else {
    b = x;
    absB = av;
    errB = bound;
  }
  // The certified local model p(x + h) ∈ v + d·h ± (bound + |h|·e1 + a2·h² + u|·|), as refineRoot.
  // Of two neighbours around the root it returns the one with the smaller |p| when the model orders
  // them; a tie within its error goes to the second-order model (closerBySecondOrder), then to
  // refineRoot's exact choice, so that every path picks the same double.
  let y = x - v / d;
  if (ax >= MIN_X) {
    const span = ax * SPAN;
    const e1 = B4 * a1 + U * Math.abs(d);
    if (y > a && y < b) {
      // Common case: the root lies within an ulp of y. The model at y and both neighbours at
      // once; done when y and one neighbour have certified opposite signs.
      const yu = nextUp(y);
      const yd = nextDown(y);
      const h0 = y - x;
      const hu = yu - x;
      const hd = yd - x;
      const m0 = v + d * h0;
      const mu = v + d * hu;
      const md = v + d * hd;
      const am0 = Math.abs(m0);
      const amu = Math.abs(mu);
      const amd = Math.abs(md);
      // max(|hu|, |hd|), as hu > hd
      // biome-ignore lint/complexity/useMathMinMax: Math.max compiles to data-dependent branches in V8
      const hm = -hd > hu ? -hd : hu;
      // One error bound for the three points (the largest |h|, the largest |m|).
      // biome-ignore lint/complexity/useMathMinMax: Math.max compiles to data-dependent branches in V8
      const amx = am0 > amu ? (am0 > amd ? am0 : amd) : amu > amd ? amu : amd;
      const err = SAFETY * (bound + hm * e1 + a2 * hm * hm + U * amx);
      if (hm <= span && am0 > err) {
        const s0 = m0 > 0 ? 1 : -1;
        if (s0 === sa) {
          // p(y) has a's sign: the root is above y.
          if (amu > err && (mu > 0 ? 1 : -1) !== sa && yu <= b) {
            if (am0 + 2 * err < amu || amu + 2 * err < am0) {
              H[5] = am0 < amu ? y : yu;
              return true;
            }
            const pick = closerBySecondOrder(x, v, d, bound, a1, a2, ax, y, yu);
            if (!Number.isNaN(pick)) {
              H[5] = pick;
              return true;
            }
            // Still a tie: the exact choice (certify.ts's closerEnd, through refineRoot).
            a = y;
            b = yu;
            absA = am0;
            absB = amu;
            errA = err;
            errB = err;
          }
        } else if (amd > err && (md > 0 ? 1 : -1) === sa && yd >= a) {
          if (amd + 2 * err < am0 || am0 + 2 * err < amd) {
            H[5] = amd < am0 ? yd : y;
            return true;
          }
          const pick = closerBySecondOrder(x, v, d, bound, a1, a2, ax, yd, y);
          if (!Number.isNaN(pick)) {
            H[5] = pick;
            return true;
          }
          a = yd;
          b = y;
          absA = amd;
          absB = am0;
          errA = err;
          errB = err;
        }
      }
    }
    // (With a and b adjacent no y lies strictly between them: the common case above cannot apply.)
    if (nextUp(a) >= b) {
      if (absA + errA < absB - errB) H[5] = a;
      else if (absB + errB < absA - errA) H[5] = b;
      else return fallBack(a, b, absA, absB, y);
      return true;
    }
    if (!(y > a && y < b) || y === x) y = sx === sa ? nextUp(x) : nextDown(x);
    for (let k = 0; k < 8; k++) {
      const hh = y - x;
      const ah = Math.abs(hh);
      if (!(ah <= span)) break;
      const m = v + d * hh;
      const am = Math.abs(m);
      const err = SAFETY * (bound + ah * e1 + a2 * hh * hh + U * am);
      if (!(am > err)) break;
      // p(y) with a's sign: the root lies above y.
      const above = (m > 0 ? 1 : -1) === sa;
      if (above) {
        a = y;
        absA = am;
        errA = err;
      } else {
        b = y;
        absB = am;
        errB = err;
      }
      if (nextUp(a) >= b) {
        if (absA + errA < absB - errB) H[5] = a;
        else if (absB + errB < absA - errA) H[5] = b;
        else return fallBack(a, b, absA, absB, y);
        return true;
      }
      y = above ? nextUp(y) : nextDown(y);
    }
  }
  return fallBack(a, b, absA, absB, y);
}

/**
 * Of two adjacent doubles p0 < p1 around a root, the one with the smaller |p| by the certified
 * second-order model about x: p(x + h) ∈ v + h·(d + h·c) ± (bound + |h|·e1 + h²·e2 + |h|³·e3 +
 * u·|m|), with c = p″(x)/2 evaluated directly (rounding ≤ B4·p̃″/2 = B4·a2), e1 and e2 covering the
 * roundings of d, c and the model, e3 the cubic and quartic remainder over the span. NaN when even
 * this cannot order them (a band of about 1e-9 ulp around the midpoint).
 */
function closerBySecondOrder(
  x: number,
  v: number,
  d: number,
  bound: number,
  a1: number,
  a2: number,
  ax: number,
  p0: number,
  p1: number,
): number {
  const c3 = Q[3] as number;
  const c4 = Q[4] as number;
  const c = (Q[2] as number) + x * (3 * c3 + 6 * c4 * x);
  const h0 = p0 - x;
  const h1 = p1 - x;
  const m0 = Math.abs(v + h0 * (d + h0 * c));
  const m1 = Math.abs(v + h1 * (d + h1 * c));
  const hm = Math.max(Math.abs(h0), Math.abs(h1));
  const e1 = B4 * a1 + 2 * U * Math.abs(d);
  const e2 = B4 * a2 + 3 * U * Math.abs(c);
  const e3 = Math.abs(c3) + 5 * Math.abs(c4) * ax;
  const err = SAFETY * (bound + hm * e1 + hm * hm * (e2 + hm * e3) + U * Math.max(m0, m1));
  if (m0 + 2 * err < m1) return p0;
  if (m1 + 2 * err < m0) return p1;
  return Number.NaN;
}

/** Hands the (narrowed) bracket to refineRoot: H[0..4] = a, b, |p(a)|, |p(b)|, start; false. */
function fallBack(a: number, b: number, absA: number, absB: number, y: number): boolean {
  H[0] = a;
  H[1] = b;
  H[2] = absA;
  H[3] = absB;
  H[4] = y;
  return false;
}
