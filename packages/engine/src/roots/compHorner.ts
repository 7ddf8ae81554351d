/**
 * Horner evaluation with a rigorous error bound: plain, and compensated (error-free transformations).
 *
 * Contract: each function evaluates c[0] + c[1] x + … + c[n] xⁿ (ascending, degree n ≥ 1) at x and
 * writes out[0] = the value, out[1] = B, a bound with |out[0] − p(x)| ≤ B for the exact p(x). When
 * |out[0]| > B the sign of out[0] is the exact sign. B is Infinity/NaN-safe in the sense that any
 * overflow makes |out[0]| > B false (callers then fall back to exact arithmetic).
 *
 * - `hornerBound`: plain Horner, B from Higham's bound |error| ≤ γ₂ₙ·p̃(|x|), p̃ = Σ|cᵢ||x|ⁱ.
 * - `compHorner`: compensated Horner (Graillat–Langlois–Louvet): TwoProduct by Dekker's splitting and
 *   Knuth's TwoSum, the rounding errors summed by a second Horner pass. The result is as accurate as
 *   plain Horner in twice the precision: |error| ≤ u|p(x)| + γ₂ₙ²·p̃(|x|).
 * - `compHornerDD`: the same for double-double coefficients c[i] + clo[i] (used for derivatives,
 *   whose coefficients i·cᵢ are kept exact as a pair).
 * When no rounding happened at all (every error term 0, no product near underflow) compHorner's
 * bound is 0: its value, and so its sign, even 0, is exact. Both bounds add an absolute underflow slack (2^-1070 (n+1) max(1,|x|)ⁿ) because error-free
 * transformations lose exactness for results below 2^-969 (needed only where p̃ is that small:
 * elsewhere the factors' margin covers it, and subnormal arithmetic, very slow, stays off the hot
 * path). Only + − × ÷ are used.
 */

import { COMP_HORNER_BOUND_FACTOR, PLAIN_HORNER_BOUND_FACTOR, UNIT_ROUNDOFF } from "../tolerances.js";

/** Dekker's splitting constant 2^27 + 1. */
export const SPLIT = 134217729;
const U = UNIT_ROUNDOFF;
/** Absolute slack per operation for lost exactness under gradual underflow. */
export const TINY = 2 ** -1070;
/**
 * When p̃ ≥ 2^-900·max(1,|x|)ⁿ the margin already built into the bound factors exceeds the underflow
 * slack by far, so the slack is skipped: it is subnormal, and subnormal arithmetic is very slow.
 */
export const SLACK_FREE = 2 ** -900;
/** Below this magnitude a product's TwoProduct error term may be inexact (gradual underflow). */
export const UNDERFLOW = 2 ** -968;

/** Plain Horner with Higham's a-priori bound (computed a posteriori from p̃(|x|)). */
export function hornerBound(c: ArrayLike<number>, n: number, x: number, out: Float64Array): void {
  const ax = x < 0 ? -x : x;
  const xm = Math.max(ax, 1);
  let s = c[n] as number;
  let a = s < 0 ? -s : s;
  let pw = 1;
  for (let i = n - 1; i >= 0; i--) {
    const ci = c[i] as number;
    s = s * x + ci;
    a = a * ax + (ci < 0 ? -ci : ci);
    pw *= xm;
  }
  out[0] = s;
  const main = PLAIN_HORNER_BOUND_FACTOR * (n * U) * a;
  out[1] = a >= pw * SLACK_FREE ? main : main + TINY * (n + 1) * pw;
}

/**
 * Compensated Horner: value accurate as if computed with 106-bit precision, with a rigorous bound
 * (0 when the evaluation was exact). Also out[2] = plain p'(x), out[3] = p̃'(|x|) = Σ i|cᵢ||x|^(i−1)
 * and out[4] = p̃''(|x|)/2 (for certify.ts's local model). `out` needs 5 entries.
 */
export function compHorner(c: ArrayLike<number>, n: number, x: number, out: Float64Array): void {
  let e = 0;
  let uf = 0;
  let t = SPLIT * x;
  const xh = t - (t - x);
  const xl = x - xh;
  const ax = x < 0 ? -x : x;
  const xm = Math.max(ax, 1);
  let s = c[n] as number;
  let a = s < 0 ? -s : s;
  let r = 0;
  let pw = 1;
  let d = 0;
  let a1 = 0;
  let a2 = 0;
  for (let i = n - 1; i >= 0; i--) {
    d = d * x + s;
    a2 = a2 * ax + a1;
    a1 = a1 * ax + a;
    const p = s * x;
    t = SPLIT * s;
    const sh = t - (t - s);
    const sl = s - sh;
    const pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
    const ci = c[i] as number;
    s = p + ci;
    const z = s - p;
    const se = p - (s - z) + (ci - z);
    const q = pe + se;
    r = r * x + q;
    e += q < 0 ? -q : q;
    if (!(p >= UNDERFLOW || p <= -UNDERFLOW)) uf = 1;
    a = a * ax + (ci < 0 ? -ci : ci);
    pw *= xm;
  }
  const v = s + r;
  out[0] = v;
  out[2] = d;
  out[3] = a1;
  out[4] = a2;
  // No rounding error anywhere (all error terms 0, no product in the underflow range): v is exact.
  if (e === 0 && uf === 0) out[1] = 0;
  else {
    const main = COMP_HORNER_BOUND_FACTOR * (U * (v < 0 ? -v : v) + n * n * U * U * a);
    out[1] = a >= pw * SLACK_FREE ? main : main + TINY * (n + 1) * pw;
  }
}

/** Compensated Horner for double-double coefficients c[i] + clo[i]. */
export function compHornerDD(
  c: ArrayLike<number>,
  clo: ArrayLike<number>,
  n: number,
  x: number,
  out: Float64Array,
): void {
  let t = SPLIT * x;
  const xh = t - (t - x);
  const xl = x - xh;
  const ax = x < 0 ? -x : x;
  const xm = Math.max(ax, 1);
  let s = c[n] as number;
  let a = s < 0 ? -s : s;
  let r = clo[n] as number;
  let pw = 1;
  for (let i = n - 1; i >= 0; i--) {
    const p = s * x;
    t = SPLIT * s;
    const sh = t - (t - s);
    const sl = s - sh;
    const pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
    const ci = c[i] as number;
    s = p + ci;
    const z = s - p;
    const se = p - (s - z) + (ci - z);
    r = r * x + (pe + se + (clo[i] as number));
    a = a * ax + (ci < 0 ? -ci : ci);
    pw *= xm;
  }
  const v = s + r;
  out[0] = v;
  const main = 2 * COMP_HORNER_BOUND_FACTOR * (U * (v < 0 ? -v : v) + n * n * U * U * a);
  out[1] = a >= pw * SLACK_FREE ? main : main + TINY * (n + 1) * pw;
}
