/**
 * realRoots(coeffs, lo, hi): the distinct real roots of p(t) = c0 + c1 t + c2 t² + … in [lo, hi],
 * sorted ascending. Any degree; `coeffs` is any array-like of finite numbers (ascending powers).
 *
 * Method (see README.md): trim zero leading coefficients, scale by powers of two (exact), clamp
 * infinite or huge ends to Cauchy's root bound (an interval reaching from near 0 far beyond 1 is
 * solved in pieces of one variable scaling each, solvePieces), drop leading terms negligible over the interval
 * (ROOTS_DEGREE_DROP, relative). Quartics first go through the hot path of quartic.ts (exact and
 * Bernstein sign tests, a single critical point, or subdivision into one-root pieces), which
 * settles almost all collision quartics; what it hands back takes the method below. Quick sign checks on p's Bernstein coefficients over [lo, hi]:
 * one sign → no root; one sign change between ends of opposite signs → exactly one root, solved
 * directly; their differences (p′'s) tell when p is monotone or has one critical point. Otherwise
 * the roots of p′ split [lo, hi] into monotone pieces (found the same way, recursively, down to a
 * quadratic solved in closed form without cancellation). The exact sign of p is decided at every
 * piece end (certify.ts: plain → compensated → BigInt); each piece whose ends have opposite exact
 * signs holds exactly one root, found by safeguarded Halley/Newton and refined on certified signs to
 * a double within 1 ulp of it. A piece end with p exactly 0 is a root (roots exactly at lo or hi,
 * exact multiple roots). Around a critical point where |p| is within the plain evaluation error
 * bound, the nearest exact sign changes of p′ become further piece ends (clusters). Such a critical
 * point where p does not change sign on either side is a double root (a grazing contact): it is
 * refined to the sign change of the exact p′ and reported.
 *
 * Accuracy: every root reported for a sign change (or exact zero) is within 1 ulp of an exact root
 * of the polynomial with the given double coefficients: of the two adjacent doubles around the
 * exact sign change, the one with the smaller exact |p| (the lower on a tie), whichever path found
 * it, so that the same polynomial in another power-of-two unit gives the same bits scaled; and
 * every exact sign change between
 * consecutive piece ends is reported. A grazing root is backward stable: an exact double root of a
 * polynomial whose coefficients differ from the given ones by at most about 2.5·n·u relatively
 * (it cannot always be within 4 ulps of an exact root: with rounded coefficients the exact
 * polynomial may have no real root there at all). Limits: coefficients spread over more than
 * ~2^1000 (scaling underflows the small ones), and evaluation overflow in the plain phases. An
 * infinite end is no limit: a root 1/c of x² − c·x + 1 on [0, ∞) is found to 1 ulp for any c.
 *
 * Errors: coeffs not array-like, a non-finite coefficient or a NaN end throws RangeError naming the
 * field; lo > hi returns [];
 * a constant (or identically zero) polynomial has no isolated roots and returns []. Iteration caps
 * throw RootSolverError (never expected). Not re-entrant (module scratch buffers).
 * `realRootsInto(coeffs, lo, hi, out)`: the same into a caller's array (cleared; returns the count).
 */

import { given } from "../sim/refusalText.js";
import { ROOTS_CAUCHY_WIDENING } from "../tolerances.js";
import { exponentOf } from "./pow2.js";
import { found, quarticRoots } from "./quartic.js";
import { ensure, solvePieces, solveRange, variableScale } from "./scaledSolve.js";

/** Horner evaluation of c0 + c1 x + … (ascending coefficients); 0 for an empty array. */
export function evalPoly(coeffs: ArrayLike<number>, x: number): number {
  let n = coeffs.length - 1;
  if (n < 0) return 0;
  let s = coeffs[n] as number;
  while (n > 0) {
    n--;
    s = s * x + (coeffs[n] as number);
  }
  return s;
}

/** The distinct real roots of c0 + c1 t + … in [lo, hi], sorted ascending (see the module header). */
export function realRoots(coeffs: ArrayLike<number>, lo: number, hi: number): number[] {
  if (coeffs?.length === 5) {
    const k = quarticRoots(coeffs, lo, hi);
    // Exact-size literals: cheaper than growing an empty array.
    if (k === 0) return [];
    if (k === 1) return [found[0] as number];
    if (k === 2) return [found[0] as number, found[1] as number];
    if (k > 0) {
      const out: number[] = [];
      for (let i = 0; i < k; i++) out.push(found[i] as number);
      return out;
    }
  }
  return general(coeffs, lo, hi, []);
}

/**
 * realRoots into a caller's array (its old contents replaced; no allocation once it has grown): for
 * callers that solve in a loop. Returns the number of roots. Same contract and results as realRoots.
 * (The roots are written by index and the length set only when it changes: `out.length = 0`
 * followed by push made V8 drop and reallocate the array's storage on every call, about 45 ns per
 * call on the benchmark's quartics, a third of the solve.)
 */
export function realRootsInto(coeffs: ArrayLike<number>, lo: number, hi: number, out: number[]): number {
  if (coeffs?.length === 5) {
    const k = quarticRoots(coeffs, lo, hi);
    if (k >= 0) {
      for (let i = 0; i < k; i++) out[i] = found[i] as number;
      if (out.length !== k) out.length = k;
      return k;
    }
  }
  out.length = 0;
  return general(coeffs, lo, hi, out).length;
}

/** Everything but the quartic hot path (quartic.ts); out is empty. */
function general(coeffs: ArrayLike<number>, lo: number, hi: number, out: number[]): number[] {
  const len = coeffs === null || coeffs === undefined ? undefined : coeffs.length;
  if (typeof len !== "number" || !(len >= 0 && len <= Number.MAX_SAFE_INTEGER && Math.floor(len) === len))
    throw new RangeError(`realRoots(coeffs): must be an array-like of finite numbers (got ${given(coeffs)})`);
  if (typeof lo !== "number" || Number.isNaN(lo))
    throw new RangeError(`realRoots(lo): must be a number (got ${given(lo)})`);
  if (typeof hi !== "number" || Number.isNaN(hi))
    throw new RangeError(`realRoots(hi): must be a number (got ${given(hi)})`);
  let n = -1;
  let maxAbs = 0;
  for (let i = 0; i < len; i++) {
    const c = coeffs[i] as number;
    if (typeof c !== "number" || !(c - c === 0)) {
      throw new RangeError(`realRoots(coeffs[${i}]): must be a finite number (got ${given(c)})`);
    }
    if (c !== 0) {
      n = i;
      const a = c < 0 ? -c : c;
      if (a > maxAbs) maxAbs = a;
    }
  }
  if (!(lo <= hi) || n < 1) return out;
  ensure(n);
  // Cauchy's bound: every root has |t| < 1 + max_{i<n} |c_i / c_n| ≤ 1 + max_i |c_i| / |c_n|.
  const bound = (1 + maxAbs / Math.abs(coeffs[n] as number)) * (1 + ROOTS_CAUCHY_WIDENING);
  const B = bound < Number.POSITIVE_INFINITY ? bound : Number.MAX_VALUE;
  if (lo < -B) lo = -B;
  if (hi > B) hi = B;
  if (lo > hi) return out;
  const M = Math.max(-lo, hi, lo, -hi);
  const xs = variableScale(n, M);
  if (xs > 0) {
    // The variable scaled by 2^-xs maps |t| down to the interval's least magnitude m; below
    // 2^-(256/n + 1) of the top the scaled terms and roots would reach the subnormal range (a root
    // 1/c of x² − c·x + 1 on [0, ∞) came out as 0): such an interval is solved in pieces.
    const m = lo > 0 ? lo : hi < 0 ? -hi : 0;
    if (m === 0 || (xs - exponentOf(m) - 1) * n > 256) {
      solvePieces(coeffs, n, maxAbs, lo, hi, out);
      return out;
    }
  }
  solveRange(coeffs, n, maxAbs, lo, hi, xs, out);
  return out;
}
