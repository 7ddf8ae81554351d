/**
 * Certified sign tests of the quartic hot path (registers: quarticRegisters.ts).
 *
 * - `signPlain(x, slot)`: the exact sign of p (coefficients Q[0..4]) at x when plain Horner with
 *   its rigorous bound (Higham, see compHorner.ts) decides it, else 0; |p(x)| into absAt[slot].
 * - `signAt(x, slot)`: the exact sign of p at x: signPlain, else certify.ts's certSign (compensated,
 *   then exact); |p(x)| into absAt[slot].
 * - `quarters(off, sg)`: one halving of the half QS[off..off+4] (ends of the sign sg, certified):
 *   true when both quarters have all coefficients of that sign beyond the margin QS[9].
 * Each halving's four rounds of averaging add at most 4u·max|b| to the rounding error: callers
 * grow the margin by ROOTS_SUBDIVISION_MARGIN_GROWTH per level (see quartic.ts).
 */

import { PLAIN_HORNER_BOUND_FACTOR, UNIT_ROUNDOFF } from "../tolerances.js";
import { certSign, lastAbsValue } from "./certify.js";
import * as reg from "./quarticRegisters.js";

/** Module-local copies of the registers (V8 folds a module's own consts; see quarticRegisters.ts). */
const Q = reg.Q;
const absAt = reg.absAt;
/** Plain Horner error bound for degree 4 (Higham, see compHorner.ts). */
export const B4 = PLAIN_HORNER_BOUND_FACTOR * 4 * UNIT_ROUNDOFF;
/**
 * Below this p̃(|x|) the plain bound would need compHorner's underflow slack (|x| ≤ 2^64 here, so
 * max(1,|x|)⁴·2^-900 ≤ 2^-600): such points are decided by certSign.
 */
export const TINY_SCALE = 2 ** -600;

const qs = new Float64Array(10);
/** Scratch of the halvings: two halves at QS[0..8], the margin QS[9]. */
export const QS: Float64Array = qs;

export function signPlain(x: number, slot: number): number {
  const c0 = Q[0] as number;
  const c1 = Q[1] as number;
  const c2 = Q[2] as number;
  const c3 = Q[3] as number;
  const c4 = Q[4] as number;
  const ax = Math.abs(x);
  const v = (((c4 * x + c3) * x + c2) * x + c1) * x + c0;
  const a =
    (((Math.abs(c4) * ax + Math.abs(c3)) * ax + Math.abs(c2)) * ax + Math.abs(c1)) * ax + Math.abs(c0);
  const av = Math.abs(v);
  absAt[slot] = av;
  return av > B4 * a && a >= TINY_SCALE ? (v > 0 ? 1 : -1) : 0;
}

export function signAt(x: number, slot: number): number {
  const sg = signPlain(x, slot);
  if (sg !== 0) return sg;
  reg.ensureLoaded();
  const se = certSign(x);
  absAt[slot] = lastAbsValue();
  return se;
}

export function quarters(off: number, sg: number): boolean {
  const b0 = qs[off] as number;
  const b1 = qs[off + 1] as number;
  const b2 = qs[off + 2] as number;
  const b3 = qs[off + 3] as number;
  const b4 = qs[off + 4] as number;
  const m = qs[9] as number;
  const l1 = 0.5 * (b0 + b1);
  const m1 = 0.5 * (b1 + b2);
  const m2 = 0.5 * (b2 + b3);
  const r3 = 0.5 * (b3 + b4);
  const l2 = 0.5 * (l1 + m1);
  const m3 = 0.5 * (m1 + m2);
  const r2 = 0.5 * (m2 + r3);
  const l3 = 0.5 * (l2 + m3);
  const r1 = 0.5 * (m3 + r2);
  const mid = 0.5 * (l3 + r1);
  // (Comparison chains, not Math.min/max: V8 compiles those to data-dependent branches.)
  return sg > 0
    ? l1 > m && l2 > m && l3 > m && mid > m && r1 > m && r2 > m && r3 > m
    : l1 < -m && l2 < -m && l3 < -m && mid < -m && r1 < -m && r2 < -m && r3 < -m;
}
