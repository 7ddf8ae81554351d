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
 */

import { exactPolySign, ulpsToExactRoot } from "./exactPoly.js";

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
