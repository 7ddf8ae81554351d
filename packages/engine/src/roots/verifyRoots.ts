/**
 * verifyRoots: checks a claimed root list against exact arithmetic (for tests and benchmarks).
 *
 * Contract: given coefficients, a finite interval [lo, hi] and the roots a solver returned, reports
 * - `maxUlps`: the largest ulpsToExactRoot over the roots (Infinity if one has no exact root
 *   within `maxUlps` steps; 0 for an empty list) and `worst`, the root that attains it;
 * - `missed`: consecutive sample points (samples + 1 evenly spaced points over [lo, hi]) between
 *   which the exact polynomial changes sign although no returned root lies between them, and sample
 *   points where it is exactly 0 that are not returned;
 * - `ordered`: the roots are strictly increasing and inside [lo, hi].
 * Pure; exact (BigInt) signs only, so it is slow: use a few dozen samples.
 *
 * `isGrazingRoot(coeffs, x)`: the contract of a grazing (double-root) report, which is not a sign
 * change: the exact p' is 0 at x or changes sign within one ulp of x, and shifting c0 by the plain
 * Horner error bound B = PLAIN_HORNER_BOUND_FACTOR·n·u·Σ|cᵢ||x|ⁱ (doubled, plus the gradual-underflow
 * slack) towards zero makes x a root or flips the sign, i.e. p(x) is within rounding noise of 0.
 */

import { PLAIN_HORNER_BOUND_FACTOR, UNIT_ROUNDOFF } from "../tolerances.js";
import { exactDerivativeSign, exactPolySign, nextDown, nextUp, ulpsToExactRoot } from "./exactPoly.js";

export interface RootCheck {
  maxUlps: number;
  worst: number | null;
  missed: Array<[number, number]>;
  ordered: boolean;
}

export function verifyRoots(
  coeffs: ArrayLike<number>,
  lo: number,
  hi: number,
  roots: readonly number[],
  samples = 48,
  maxUlps = 64,
): RootCheck {
  let worstU = 0;
  let worst: number | null = null;
  let ordered = true;
  for (let i = 0; i < roots.length; i++) {
    const r = roots[i] as number;
    if (!(r >= lo && r <= hi) || (i > 0 && !(r > (roots[i - 1] as number)))) ordered = false;
    const u = ulpsToExactRoot(coeffs, r, maxUlps);
    if (u > worstU || worst === null) {
      worstU = u;
      worst = r;
    }
  }
  const missed: Array<[number, number]> = [];
  const has = (a: number, b: number) => roots.some((r) => r >= a && r <= b);
  let prevX = lo;
  let prevS = exactPolySign(coeffs, lo);
  if (prevS === 0 && !has(lo, lo)) missed.push([lo, lo]);
  for (let k = 1; k <= samples; k++) {
    const x = k === samples ? hi : lo + ((hi - lo) * k) / samples;
    const s = exactPolySign(coeffs, x);
    if (s === 0) {
      if (!has(x, x)) missed.push([x, x]);
    } else if (prevS !== 0 && s !== prevS && !has(prevX, x)) {
      missed.push([prevX, x]);
    }
    prevX = x;
    prevS = s;
  }
  return { maxUlps: worstU, worst, missed, ordered };
}

/** Whether x satisfies the grazing-root contract (see the module header). */
export function isGrazingRoot(coeffs: ArrayLike<number>, x: number): boolean {
  const d = exactDerivativeSign(coeffs, x);
  const critical =
    d === 0 || exactDerivativeSign(coeffs, nextUp(x)) !== d || exactDerivativeSign(coeffs, nextDown(x)) !== d;
  if (!critical) return false;
  const n = coeffs.length - 1;
  let abs = 0;
  let pw = 1;
  const ax = Math.abs(x);
  for (let i = n; i >= 0; i--) {
    abs = abs * ax + Math.abs(coeffs[i] as number);
    if (i > 0) pw *= Math.max(1, ax);
  }
  // The solver's plain bound, doubled, plus its gradual-underflow slack (values below ~2^-1000).
  const bound = 2 * PLAIN_HORNER_BOUND_FACTOR * n * UNIT_ROUNDOFF * abs + 2 ** -1069 * (n + 1) * pw;
  const s = exactPolySign(coeffs, x);
  if (s === 0) return true;
  const shifted = Array.from(coeffs);
  shifted[0] = (shifted[0] as number) - s * bound;
  return exactPolySign(shifted, x) !== s;
}
