/**
 * Certified signs and certified root refinement for the polynomial being solved.
 *
 * The solver's decisions (which piece holds a root, which side of a root a point is on) are taken
 * on exact signs: `certSign(x)` first tries plain Horner with its error bound, then compensated
 * Horner with its bound, and only when both are inconclusive (|p(x)| at the rounding-noise level,
 * i.e. within a hair of a root, or overflow) computes the exact sign with BigInt (exactPoly.ts).
 *
 * `refineRoot(a, b, sa, x0)` takes a bracket a < b whose exact signs are sa at a and −sa at b and
 * returns a double within one ulp of an exact root in [a, b]: a few Newton steps driven by
 * compensated values (each step's sign certified, so the bracket stays valid), then halving in the
 * ordering of doubles until the bracket is two adjacent doubles; it returns the end with the smaller
 * |p| (or a point where p is exactly 0). Bounded by ROOTS_MAX_ITERATIONS, else RootSolverError.
 *
 * The derivative's certified sign changes (critical points, for grazing roots) are in
 * criticalPoint.ts, which `load` gives the same polynomial.
 *
 * State: the polynomial is loaded once per realRoots call with `load` (module scratch, no allocation
 * on the hot path; the solver is not re-entrant and needs no re-entrancy).
 */

import {
  PLAIN_HORNER_BOUND_FACTOR,
  ROOTS_MAX_ITERATIONS,
  ROOTS_MODEL_MIN_X,
  ROOTS_MODEL_SAFETY,
  ROOTS_MODEL_SPAN,
  UNIT_ROUNDOFF,
} from "../tolerances.js";
import { RootSolverError, splitPoint } from "./bracket.js";
import { compHorner, hornerBound } from "./compHorner.js";
import { loadForCriticalPoints } from "./criticalPoint.js";
import { exactAbsCompare, exactPolySign, nextDown, nextUp } from "./exactPoly.js";
import { mulPow2 } from "./pow2.js";

const ev = new Float64Array(5);
let P: Float64Array = new Float64Array(8);
let deg = 0;
let orig: ArrayLike<number> = P;
/** |value| of the last certSign evaluation (compensated when it was computed), for choosing ends. */
const last = new Float64Array(1); // |value| at the last certSign point (typed array: no boxing)
/** Whether the last certSign found |p| within the plain Horner error bound (rounding noise). */
let lastNoisy = false;

/** Exponent of the variable scaling: the caller's t is 2^xScale times the solver's s. */
let xScale = 0;

/**
 * Load the scaled polynomial P of degree n; `original` holds the caller's exact coefficients, and
 * P(s) has the sign of original(2^xs·s). criticalPoint.ts gets the same polynomial.
 */
export function load(scaled: Float64Array, n: number, original: ArrayLike<number>, xs: number): void {
  P = scaled;
  deg = n;
  orig = original;
  xScale = xs;
  loadForCriticalPoints(scaled, n, original, xs);
}

/** Exact sign of P at x (plain, then compensated, then BigInt). Sets last[0] = |value|. */
export function certSign(x: number): number {
  if (x === 0) {
    const c0 = orig[0] as number;
    lastNoisy = c0 === 0;
    last[0] = Math.abs(P[0] as number);
    return c0 > 0 ? 1 : c0 < 0 ? -1 : 0;
  }
  hornerBound(P, deg, x, ev);
  let v = ev[0] as number;
  if (Math.abs(v) > (ev[1] as number)) {
    lastNoisy = false;
    last[0] = Math.abs(v);
    return v > 0 ? 1 : -1;
  }
  lastNoisy = true;
  compHorner(P, deg, x, ev);
  v = ev[0] as number;
  last[0] = Math.abs(v);
  const bound = ev[1] as number;
  if (Math.abs(v) > bound || bound === 0) return v > 0 ? 1 : v < 0 ? -1 : 0;
  return exactPolySign(orig, xScale === 0 ? x : mulPow2(x, xScale));
}

/** |value| at the last certSign point. */
export function lastAbsValue(): number {
  return last[0] as number;
}

/** Whether the last certSign point had |p| within the plain evaluation error bound. */
export function lastWasNoisy(): boolean {
  return lastNoisy;
}

/**
 * A double within one ulp of an exact root in [a, b] (exact signs sa at a, −sa at b). One
 * compensated evaluation at x0 gives p(x0) ± B0 and p'(x0) ± B1; nearby doubles y = x0 + h
 * (|h| ≤ 2^-30 |x0|, h exact by Sterbenz) are then decided by the certified local model
 * p(y) ∈ p(x0) + p'(x0) h ± (B0 + |h| B1 + p̃''(|x0|)/2 · h² + rounding), walking from the Newton
 * estimate one ulp at a time: usually one compensated evaluation and two model checks per root.
 * When the model cannot decide, `refineGeneric` continues with full evaluations.
 */
export function refineRoot(a: number, b: number, sa: number, absA: number, absB: number, x0: number): number {
  const x = x0 > a && x0 < b ? x0 : splitPoint(a, b);
  compHorner(P, deg, x, ev);
  const t0 = ev[0] as number;
  const b0 = ev[1] as number;
  const t1 = ev[2] as number;
  const at0 = t0 < 0 ? -t0 : t0;
  let s: number;
  if (at0 > b0 || b0 === 0) s = t0 > 0 ? 1 : t0 < 0 ? -1 : 0;
  else {
    s = exactPolySign(orig, xScale === 0 ? x : mulPow2(x, xScale));
  }
  if (s === 0) return x;
  if (s === sa) {
    a = x;
    absA = at0;
  } else {
    b = x;
    absB = at0;
  }
  if (nextUp(a) >= b) return closerEnd(a, b);
  const ax = x < 0 ? -x : x;
  let y = x - t0 / t1;
  if (ax >= MODEL_MIN_X) {
    const H = ax * MODEL_SPAN;
    const e1 =
      PLAIN_HORNER_BOUND_FACTOR * deg * UNIT_ROUNDOFF * (ev[3] as number) + UNIT_ROUNDOFF * Math.abs(t1);
    const a2 = ev[4] as number;
    if (!(y > a && y < b) || y === x) y = s === sa ? nextUp(x) : nextDown(x);
    for (let k = 0; k < 8; k++) {
      const h = y - x;
      const ah = h < 0 ? -h : h;
      if (!(ah <= H)) break;
      const v = t0 + t1 * h;
      const av = v < 0 ? -v : v;
      const err = MODEL_SAFETY * (b0 + ah * e1 + a2 * h * h + UNIT_ROUNDOFF * av);
      if (!(av > err)) break; // undecided: full evaluation below
      if ((v > 0 ? 1 : -1) === sa) {
        a = y;
        absA = av;
        if (nextUp(a) >= b) return closerEnd(a, b);
        y = nextUp(y);
      } else {
        b = y;
        absB = av;
        if (nextUp(a) >= b) return closerEnd(a, b);
        y = nextDown(y);
      }
    }
  }
  return refineGeneric(a, b, sa, absA, absB, y);
}

/**
 * Of two adjacent doubles a < b around a root, the one with the smaller exact |p| (a on a tie):
 * the canonical choice, the same whichever path or scale found the bracket (a root solved at
 * another time scale, 2^k t, gives the same bits times 2^k). Compensated values decide unless
 * their difference is within their bounds; then exact arithmetic does.
 */
export function closerEnd(a: number, b: number): number {
  compHorner(P, deg, a, ev);
  const va = Math.abs(ev[0] as number);
  const ba = ev[1] as number;
  compHorner(P, deg, b, ev);
  const vb = Math.abs(ev[0] as number);
  const bb = ev[1] as number;
  if (va + ba < vb - bb) return a;
  if (vb + bb < va - ba) return b;
  const sa = xScale === 0 ? a : mulPow2(a, xScale);
  const sb = xScale === 0 ? b : mulPow2(b, xScale);
  return exactAbsCompare(orig, sa, sb) <= 0 ? a : b;
}

/** The local model's span, smallest |x0| and safety factor (tolerances.ts says why). */
export const MODEL_SPAN = ROOTS_MODEL_SPAN;
export const MODEL_MIN_X = ROOTS_MODEL_MIN_X;
export const MODEL_SAFETY = ROOTS_MODEL_SAFETY;

/** Certified refinement by full evaluations (Newton steps, then halving). */
function refineGeneric(a: number, b: number, sa: number, absA: number, absB: number, x0: number): number {
  let x = x0 > a && x0 < b ? x0 : splitPoint(a, b);
  let step = 1;
  let lastDir = 0;
  for (let it = 0; it < ROOTS_MAX_ITERATIONS; it++) {
    compHorner(P, deg, x, ev);
    const v = ev[0] as number;
    const av = v < 0 ? -v : v;
    const bound = ev[1] as number;
    let s: number;
    if (av > bound || bound === 0) s = v > 0 ? 1 : v < 0 ? -1 : 0;
    else {
      s = exactPolySign(orig, xScale === 0 ? x : mulPow2(x, xScale));
    }
    if (s === 0) return x;
    const dir = s === sa ? 1 : -1;
    if (dir > 0) {
      a = x;
      absA = av;
    } else {
      b = x;
      absB = av;
    }
    if (nextUp(a) >= b) return closerEnd(a, b);
    let xn: number;
    if (it < 8) {
      xn = x - v / (ev[2] as number);
      // At least one ulp towards the root, doubling while the steps keep the same direction.
      step = dir === lastDir ? step * 2 : 1;
      if (dir > 0 ? !(xn > x) : !(xn < x)) {
        xn = x;
        for (let k = 0; k < step; k++) xn = dir > 0 ? nextUp(xn) : nextDown(xn);
      }
      if (!(xn > a && xn < b)) xn = splitPoint(a, b);
    } else {
      xn = splitPoint(a, b);
    }
    lastDir = dir;
    x = xn;
  }
  throw new RootSolverError(
    `refineRoot: no convergence in ${ROOTS_MAX_ITERATIONS} iterations on [${a}, ${b}]`,
  );
}
