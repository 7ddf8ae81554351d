/**
 * Certified critical points of the polynomial being solved, for grazing (double-root) detection and
 * the repair of pieces where p is at rounding-noise level (level0.ts).
 *
 * `criticalPoint(x, lo, hi, out)` refines an approximate critical point x to where the exact
 * derivative p' changes sign; `nearestCritical(x, limit, out)` finds the nearest such sign change
 * between x and limit. Both decide on exact signs of p': plain Horner with its bound, else
 * compensated Horner on the double-double coefficients i·cᵢ with its error bound, else BigInt
 * (exactPoly.ts); both write the two adjacent
 * doubles around the sign change (equal where p' is exactly 0). Bisection is bounded by
 * ROOTS_MAX_ITERATIONS, else RootSolverError.
 *
 * State: certify.ts's `load` gives this module the same polynomial (module scratch; the solver is
 * not re-entrant). The derivative is built from it at each call (only grazing checks need it).
 */

import { ROOTS_MAX_ITERATIONS } from "../tolerances.js";
import { RootSolverError, splitPoint } from "./bracket.js";
import { compHornerDD, hornerBound } from "./compHorner.js";
import { exactDerivativeSign, nextDown, nextUp } from "./exactPoly.js";
import { mulPow2 } from "./pow2.js";

const ev = new Float64Array(5);
let P: Float64Array = new Float64Array(8);
let dHi = new Float64Array(8);
let dLo = new Float64Array(8);
let deg = 0;
let orig: ArrayLike<number> = P;
/** Exponent of the variable scaling: the caller's t is 2^xScale times the solver's s. */
let xScale = 0;

/** The polynomial certify.ts's `load` was given (scaled P of degree n, the caller's originals, xs). */
export function loadForCriticalPoints(
  scaled: Float64Array,
  n: number,
  original: ArrayLike<number>,
  xs: number,
): void {
  P = scaled;
  deg = n;
  orig = original;
  xScale = xs;
}

/** Load the exact derivative i·cᵢ as double-double pairs (lazy: only for grazing checks). */
function loadDerivative(): void {
  if (dHi.length < deg) {
    dHi = new Float64Array(deg);
    dLo = new Float64Array(deg);
  }
  for (let i = 1; i <= deg; i++) {
    const c = P[i] as number;
    const h = i * c;
    // TwoProduct(i, c) by splitting: i is a small integer (exact in 26 bits), so only c is split.
    const t = 134217729 * c;
    const ch = t - (t - c);
    const cl = c - ch;
    dHi[i - 1] = h;
    dLo[i - 1] = i * cl - (h - i * ch);
  }
}

/**
 * Exact sign of P' at x (plain Horner on the high parts, then compensated double-double, then
 * BigInt). The plain value decides when it exceeds twice Higham's bound: once for the rounding of
 * the evaluation, once for the low parts it leaves out (|dLo[i]| <= u |dHi[i]|, so their sum is
 * within u times the bound's p~(|x|), far below the bound's 2.5 n u p~(|x|)). Every probe of
 * nearestCritical's search away from a critical point is decided so: a disc sliding along a channel
 * exactly its diameter wide met a double root at each wall's end point, and some 110 compensated
 * evaluations per solve there cost ten times the solve of a channel 0.01 wider.
 */
function certDerivSign(x: number): number {
  hornerBound(dHi, deg - 1, x, ev);
  const p = ev[0] as number;
  if (Math.abs(p) > 2 * (ev[1] as number)) return p > 0 ? 1 : -1;
  compHornerDD(dHi, dLo, deg - 1, x, ev);
  const v = ev[0] as number;
  if (Math.abs(v) > (ev[1] as number)) return v > 0 ? 1 : -1;
  return exactDerivativeSign(orig, xScale === 0 ? x : mulPow2(x, xScale));
}

/**
 * Refine an approximate critical point x of P inside (lo, hi) to where the exact P' changes sign.
 * Writes the two adjacent doubles around the sign change (equal when P' is exactly 0 there) into
 * out[0], out[1] and returns true; returns false (out = x, x) when P' has no sign change in
 * (lo, hi) found by probing at 1, 2, 4, … ulps from x (then x is not a confirmed critical point).
 */
export function criticalPoint(x: number, lo: number, hi: number, out: Float64Array): boolean {
  out[0] = x;
  out[1] = x;
  if (deg < 2) return false;
  loadDerivative();
  const s0 = certDerivSign(x);
  if (s0 === 0) return true;
  // Search both directions at 1, 2, 4, … ulps (up to the neighbouring points) for the nearest sign
  // change of P' (the structural critical point may be far off next to a multiple root), then bisect.
  const ax = x < 0 ? -x : x;
  const ulp = x === 0 ? Number.MIN_VALUE : nextUp(ax) - ax;
  // The last probe on each side is the double next to the limit, so the whole of (lo, hi) is covered.
  const upLimit = nextDown(hi);
  const downLimit = nextUp(lo);
  let prevUp = x;
  let prevDown = x;
  let upDone = !(x < upLimit);
  let downDone = !(x > downLimit);
  let off = ulp;
  for (let k = 0; k <= 60 && !(upDone && downDone); k++, off *= 2) {
    if (!upDone) {
      let up = x + off;
      if (!(up < upLimit)) {
        up = upLimit;
        upDone = true;
      }
      if (up > prevUp) {
        const s = certDerivSign(up);
        if (s !== s0) {
          bisectDerivative(prevUp, up, s0, s, out);
          return true;
        }
        prevUp = up;
      }
    }
    if (!downDone) {
      let down = x - off;
      if (!(down > downLimit)) {
        down = downLimit;
        downDone = true;
      }
      if (down < prevDown) {
        const s = certDerivSign(down);
        if (s !== s0) {
          bisectDerivative(down, prevDown, s, s0, out);
          return true;
        }
        prevDown = down;
      }
    }
  }
  return false;
}

/**
 * The nearest sign change of the exact P' strictly between x and limit (either side of x): probes
 * at 1, 2, 4, … ulps from x towards limit (the last probe is the double next to limit), starting
 * from the sign just beside x, then bisects. Writes the two adjacent doubles around it into out[0] <
 * out[1] (equal when P' is exactly 0 there) and returns true; false when there is none.
 */
export function nearestCritical(x: number, limit: number, out: Float64Array): boolean {
  return searchCritical(x, limit, out, true);
}

/** nearestCritical without its shortcut (movesAwayFromZero): for the test that both agree. */
export function probeCritical(x: number, limit: number, out: Float64Array): boolean {
  return searchCritical(x, limit, out, false);
}

function searchCritical(x: number, limit: number, out: Float64Array, shortcut: boolean): boolean {
  if (deg < 2 || x === limit) return false;
  loadDerivative();
  const up = limit > x;
  const start = up ? nextUp(x) : nextDown(x);
  const end = up ? nextDown(limit) : nextUp(limit);
  if (up ? !(start < end) : !(start > end)) return false;
  const s0 = certDerivSign(start);
  if (s0 === 0) {
    out[0] = out[1] = start;
    return true;
  }
  // p' moving away from 0 all the way (p'' of the sign s0 on the way up, -s0 on the way down): no
  // probe below could find another sign, and the search would end with none (next to a double
  // root, whose p' grows steadily on both sides, that cost ~55 probes each way; see certDerivSign).
  if (shortcut && movesAwayFromZero(up ? start : end, up ? end : start, up ? s0 : -s0)) return false;
  const ax = x < 0 ? -x : x;
  let off = x === 0 ? Number.MIN_VALUE : nextUp(ax) - ax;
  let prev = start;
  for (let k = 0; k <= 1100; k++, off *= 2) {
    let y = up ? start + off : start - off;
    const last = up ? !(y < end) : !(y > end);
    if (last) y = end;
    if (up ? y > prev : y < prev) {
      const s = certDerivSign(y);
      if (s !== s0) {
        if (up) bisectDerivative(prev, y, s0, s, out);
        else bisectDerivative(y, prev, s, s0, out);
        return true;
      }
      prev = y;
    }
    if (last) return false;
  }
  return false;
}

const d2 = new Float64Array(3);
const d3 = new Float64Array(2);

/**
 * Whether P'' certainly has the sign `sign` on all of [a, b] (a < b), for P of degree 2 to 4: P''
 * of that exact sign at both ends and P''' (of degree at most 1) of one exact sign at both ends, so
 * that P'' is monotone between them. False when undecided (higher degree, or values too near 0).
 */
export function movesAwayFromZero(a: number, b: number, sign: number): boolean {
  if (deg < 2 || deg > 4) return false;
  // The coefficients of P'' and P''', each rounded once (relative error <= u: see signOrZero).
  for (let i = 2; i <= deg; i++) d2[i - 2] = i * (i - 1) * (P[i] as number);
  if (deg === 2) return Math.sign(d2[0] as number) === sign;
  for (let i = 3; i <= deg; i++) d3[i - 3] = i * (i - 1) * (i - 2) * (P[i] as number);
  const s3 = signOrZero(d3, deg - 3, a);
  return (
    s3 !== 0 &&
    signOrZero(d3, deg - 3, b) === s3 &&
    signOrZero(d2, deg - 2, a) === sign &&
    signOrZero(d2, deg - 2, b) === sign
  );
}

/**
 * The exact sign at x of the polynomial whose exact coefficients are within a relative u of c[0..n],
 * or 0 when plain Horner cannot tell: the value must exceed twice Higham's bound (once for the
 * evaluation, once for the coefficients' rounding, as in certDerivSign).
 */
function signOrZero(c: Float64Array, n: number, x: number): number {
  if (n === 0) return Math.sign(c[0] as number);
  hornerBound(c, n, x, ev);
  const v = ev[0] as number;
  return Math.abs(v) > 2 * (ev[1] as number) ? (v > 0 ? 1 : -1) : 0;
}

/** Bisect a sign change of P' between a < b (exact signs sa, sb) down to adjacent doubles. */
function bisectDerivative(a: number, b: number, sa: number, sb: number, out: Float64Array): void {
  if (sa === 0 || sb === 0) {
    out[0] = out[1] = sa === 0 ? a : b;
    return;
  }
  for (let it = 0; it < ROOTS_MAX_ITERATIONS; it++) {
    const m = splitPoint(a, b);
    if (m === a) {
      out[0] = a;
      out[1] = b;
      return;
    }
    const s = certDerivSign(m);
    if (s === 0) {
      out[0] = out[1] = m;
      return;
    }
    if (s === sa) a = m;
    else b = m;
  }
  throw new RootSolverError(
    `criticalPoint: no convergence in ${ROOTS_MAX_ITERATIONS} iterations on [${a}, ${b}]`,
  );
}
