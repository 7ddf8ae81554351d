/**
 * The quartic hot path of realRoots (collision quartics): cheap certified early exits that settle
 * almost every call; anything unusual is handed back to the general method (realRoots.ts).
 *
 * `quarticRoots(coeffs, lo, hi)`: coeffs of length 5. Returns the number of roots in [lo, hi]
 * (ascending and distinct in `found[0..count)`, each within 1 ulp of an exact root of the
 * polynomial with the given double coefficients) when it settled the call, −1 when it hands it
 * back: invalid input (realRoots reports it), c4 = 0, lo ≥ hi, coefficients or interval needing
 * scaling, p at rounding-noise level at a piece end or at the critical point (a root at or near
 * lo or hi, touching discs, grazing), roots closer than h/2^MAX_DEPTH (clusters, double roots).
 *
 * Steps, cheapest first:
 * 1. Exact: lo ≥ 0 and every coefficient of the sign of c0 ≠ 0 → no root (no rounding at all).
 * 2. Cauchy's clamp of [lo, hi] (as realRoots); the Bernstein coefficients b0…b4 of p on
 *    [lo, lo + h], h = (hi − lo)(1 + 4u) ≥ hi − lo, from a Taylor shift, with a margin bounding
 *    their rounding errors (as bernstein.ts). All of one sign → no root (convex hull property).
 * 3. Ends of one sign: one de Casteljau halving; both halves of one sign → no root.
 * 4. Ends of one sign and p′'s Bernstein coefficients (the differences) with exactly one certified
 *    sign change: p has exactly one critical point in [lo, lo + h] — the derivative splitting of
 *    the issue with a single split point: the critical point x* by safeguarded Halley on p′, the
 *    exact sign of p at x* (plain Horner with its bound; at noise level → handed back, as the
 *    general method repairs such points exactly), then p is monotone on [lo, x*] and [x*, lo + h]:
 *    no root, or one root on each side whose ends differ in sign.
 * 5. Otherwise, Bernstein subdivision: de Casteljau halving, left to right, at most MAX_DEPTH
 *    levels, the margin grown by MARGIN_PER_LEVEL per halving (a halving's four rounds of averaging
 *    add at most 4u·max|b| ≤ 4u·scale). Descartes' rule for the Bernstein basis on each piece whose
 *    coefficients all have certified signs: no sign change → no root; exactly one → exactly one
 *    simple root inside. A one-root piece's real ends lo + s·h are replaced by the nearest doubles,
 *    whose exact signs must match the certified signs at the real ends (so no root lies between a
 *    double and its real end). Pieces cover [lo, lo + h], so every root is found exactly once.
 * Each root: safeguarded Halley in its bracket (newton.ts's iteration, stopped at 2^-11), then one
 * compensated Horner evaluation and the certified local model of certify.ts's refineRoot decide
 * the two doubles around it (refineRoot itself finishes the rare undecided cases, exact fallback
 * included). Loops are bounded (ROOTS_MAX_ITERATIONS, MAX_DEPTH); RootSolverError as newton.ts.
 *
 * Speed notes (V8): doubles pass between the functions here through module-local typed arrays,
 * never as arguments or results (V8 boxes those for calls it does not inline); module-local typed
 * arrays and constants are constants to the optimiser, imported ones are not (hence local copies).
 * That is also why this is one long module rather than several: split into per-root kernels and
 * subdivision (registers shared as imported typed arrays) it measured +9% instructions and +6%
 * cycles per call on the benchmark's quartics.
 */

import {
  COMP_HORNER_BOUND_FACTOR,
  PLAIN_HORNER_BOUND_FACTOR,
  ROOTS_HOT_HALLEY_STOP,
  ROOTS_MAX_ITERATIONS,
  ROOTS_SUBDIVISION_MARGIN_GROWTH,
  UNIT_ROUNDOFF,
} from "../tolerances.js";
import { RootSolverError, splitPoint } from "./bracket.js";
import {
  certSign,
  lastAbsValue,
  load,
  MODEL_MIN_X,
  MODEL_SAFETY,
  MODEL_SPAN,
  refineRoot,
} from "./certify.js";

const U = UNIT_ROUNDOFF;
/** Coefficient magnitudes and interval ends realRoots uses unscaled (as realRoots.ts). */
const SMALL = 2 ** -64;
const BIG = 2 ** 64;
/** Plain Horner error bound for degree 4 (Higham, see compHorner.ts). */
const B4 = PLAIN_HORNER_BOUND_FACTOR * 4 * U;
/**
 * Below this p̃(|x|) the plain bound would need compHorner's underflow slack (|x| ≤ 2^64 here, so
 * max(1,|x|)⁴·2^-900 ≤ 2^-600): such points are decided by certSign.
 */
const TINY_SCALE = 2 ** -600;
/** Halving depth limit: pieces of h/256. Deeper cases (near-double roots) take the general path. */
const MAX_DEPTH = 8;
/** Margin growth per halving (see tolerances.ts). */
const MARGIN_PER_LEVEL = ROOTS_SUBDIVISION_MARGIN_GROWTH;
/** 1/C(4,2), rounded (the margin covers it, as bernstein.ts's 1/C(n,k)). */
const SIXTH = 1 / 6;
/** Halley's stopping rule (see tolerances.ts); NEWTON_STEPS as newton.ts. */
const EARLY = ROOTS_HOT_HALLEY_STOP;
const NEWTON_STEPS = 20;
/**
 * Local copies of imported constants: V8 folds a module's own constants into its optimised code,
 * not imported ones (each use of an import is a load and a check).
 */
const MAX_IT = ROOTS_MAX_ITERATIONS;
const SPAN = MODEL_SPAN;
const MIN_X = MODEL_MIN_X;
const SAFETY = MODEL_SAFETY;
const COMP = COMP_HORNER_BOUND_FACTOR;
/** compHorner.ts's constants: Dekker's split, underflow limits (see there). */
const SPLIT = 134217729;
const UNDERFLOW = 2 ** -968;
const SLACK_FREE = 2 ** -900;
const TINY = 2 ** -1070;

/** Registers: c0…c4, lo, hi, h, then p′'s coefficients c1, 2c2, 3c3, 4c4, 0 (at P1). */
const Q = new Float64Array(13);
const P1 = 8;
/** Halley's arguments and result: bracket a, b; plain values fa, fb of opposite signs; guess; root. */
const H = new Float64Array(6);
/** Bernstein coefficients b0…b4 on [lo, lo + h] and their margin. */
const BC = new Float64Array(6);
/** After an exact zero at lo, a one-root piece [lo, b] is bracketed from lo + (b − lo)·ZERO_OFFSET. */
const ZERO_OFFSET = 2 ** -10;
/** p(lo) = 0 exactly (already reported); the signs below are those of p just after lo. */
let zeroAtLo = false;
/** Exact sign of p(lo) for isolate (the left end of its first pieces). */
let loSign = 0;
/** Pending pieces of the subdivision: 5 coefficients, left end s and width w (fractions of h), depth. */
const stack = new Float64Array(8 * (MAX_DEPTH + 2));
/** One-root pieces: left end s, right end s, control-polygon zero s, certified sign at the left end. */
const ones = new Float64Array(4 * 4);
/** |p| at the last two signAt points. */
const absAt = new Float64Array(2);

export function quarticRoots(coeffs: ArrayLike<number>, lo: number, hi: number): number {
  nFound = 0;
  return settle(coeffs, lo, hi) ? nFound : -1;
}

/** The roots found by the last quarticRoots call (found[0..count)), ascending. */
export const found = new Float64Array(8);
let nFound = 0;

function settle(coeffs: ArrayLike<number>, lo: number, hi: number): boolean {
  const c0 = coeffs[0] as number;
  const c1 = coeffs[1] as number;
  const c2 = coeffs[2] as number;
  const c3 = coeffs[3] as number;
  const c4 = coeffs[4] as number;
  if (
    typeof c0 !== "number" ||
    typeof c1 !== "number" ||
    typeof c2 !== "number" ||
    typeof c3 !== "number" ||
    typeof c4 !== "number" ||
    typeof lo !== "number" ||
    typeof hi !== "number" ||
    !(lo < hi) ||
    c4 === 0 ||
    !(c0 - c0 + (c1 - c1) + (c2 - c2) + (c3 - c3) + (c4 - c4) === 0)
  ) {
    return false;
  }
  // Exact early exit (no rounding): on t ≥ 0, coefficients all of the sign of c0 ≠ 0 keep p there.
  if (
    lo >= 0 &&
    (c0 > 0 ? c1 >= 0 && c2 >= 0 && c3 >= 0 && c4 >= 0 : c0 < 0 && c1 <= 0 && c2 <= 0 && c3 <= 0 && c4 <= 0)
  ) {
    return true;
  }
  const a0 = Math.abs(c0);
  const a1 = Math.abs(c1);
  const a2 = Math.abs(c2);
  const a3 = Math.abs(c3);
  const a4 = Math.abs(c4);
  const maxAbs = Math.max(a0, a1, a2, a3, a4);
  if (!(maxAbs >= SMALL && maxAbs <= BIG)) return false;
  // Cauchy's bound, as realRoots: every root has |t| < 1 + max|c_i| / |c4|. (No division unless
  // an end may lie beyond it: |x|·|c4| ≤ maxAbs, computed, gives |x| < the bound.)
  if (hi * a4 > maxAbs || -lo * a4 > maxAbs) {
    const bound = (1 + maxAbs / a4) * (1 + 2 ** -48);
    if (lo < -bound) lo = -bound;
    if (hi > bound) hi = bound;
    if (lo > hi) return true;
  }
  const M = lo < 0 ? (-lo > hi ? -lo : hi < 0 ? -hi : hi) : hi;
  if (!(lo < hi && M <= BIG && M >= SMALL)) return false;
  // Bernstein coefficients on [lo, lo + h]: Taylor shift to lo (and of |p| to |lo|, the scale).
  let t0 = c0;
  let t1 = c1;
  let t2 = c2;
  let t3 = c3;
  let s0 = a0;
  let s1 = a1;
  let s2 = a2;
  let s3 = a3;
  if (lo !== 0) {
    const al = Math.abs(lo);
    t3 += lo * c4;
    t2 += lo * t3;
    t1 += lo * t2;
    t0 += lo * t1;
    t3 += lo * c4;
    t2 += lo * t3;
    t1 += lo * t2;
    t3 += lo * c4;
    t2 += lo * t3;
    t3 += lo * c4;
    s3 += al * a4;
    s2 += al * s3;
    s1 += al * s2;
    s0 += al * s1;
    s3 += al * a4;
    s2 += al * s3;
    s1 += al * s2;
    s3 += al * a4;
    s2 += al * s3;
    s3 += al * a4;
  }
  const h = (hi - lo) * (1 + 4 * U);
  const h2 = h * h;
  const h3 = h2 * h;
  const h4 = h2 * h2;
  const e1 = t1 * h * 0.25;
  const e2 = t2 * h2 * SIXTH;
  const e3 = t3 * h3 * 0.25;
  const e4 = c4 * h4;
  const margin = 24 * U * (s0 + s1 * h + s2 * h2 + s3 * h3 + a4 * h4);
  if (!(margin < Number.POSITIVE_INFINITY)) return false;
  const b0 = t0;
  const b1 = t0 + e1;
  const b2 = t0 + 2 * e1 + e2;
  const b3 = t0 + 3 * e1 + 3 * e2 + e3;
  const b4 = t0 + 4 * e1 + 6 * e2 + 4 * e3 + e4;
  // Depth 0 (most calls end here): every coefficient of one sign, no root.
  if (Math.min(b0, b1, b2, b3, b4) > margin || Math.max(b0, b1, b2, b3, b4) < -margin) return true;
  // The exact sign of p(lo) = b0: certified by the margin, else (p(lo) at rounding-noise level:
  // touching discs) decided exactly; p(lo) = 0 goes to the general path.
  let sLo = b0 > margin ? 1 : b0 < -margin ? -1 : 0;
  zeroAtLo = false;
  if (sLo === 0) {
    Q[0] = c0;
    Q[1] = c1;
    Q[2] = c2;
    Q[3] = c3;
    Q[4] = c4;
    curCoeffs = coeffs;
    loaded = false;
    ensureLoaded();
    sLo = certSign(lo);
    if (sLo === 0) {
      // p(lo) = 0 exactly (discs touching at lo): the Bernstein coefficients of p(t)/(t − lo) on
      // the same interval are (4/j)·b_j, j ≥ 1, so b1…b4 of one sign leave lo as the only root.
      pushRoot(lo);
      if (Math.min(b1, b2, b3, b4) > margin || Math.max(b1, b2, b3, b4) < -margin) return true;
      // Otherwise the sign just after lo is b1's, and the one-sign tests below hold for p(t)/(t − lo)
      // as well; only the single-extremum case is settled here (lo and no other root).
      if (!(Math.abs(b1) > margin)) return false;
      sLo = b1 > 0 ? 1 : -1;
      zeroAtLo = true;
    }
    if (sLo > 0 ? Math.min(b1, b2, b3, b4) > margin : Math.max(b1, b2, b3, b4) < -margin) return true;
  }
  const sameEnds = sLo > 0 ? b4 > margin : b4 < -margin;
  if (sameEnds) {
    // One de Casteljau halving often proves one sign on both halves (margin grown as in isolate).
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
    const m = margin * (1 + MARGIN_PER_LEVEL);
    const okL = sLo > 0 ? Math.min(l1, l2, l3, mid) > m : Math.max(l1, l2, l3, mid) < -m;
    const okR = sLo > 0 ? Math.min(mid, r1, r2, r3) > m : Math.max(mid, r1, r2, r3) < -m;
    if (okL && okR) return true;
    // A second halving of the undecided half (or halves) settles many more near misses (the
    // halves' common end mid must have the sign too).
    if (sLo > 0 ? mid > m : mid < -m) {
      QS[0] = b0;
      QS[1] = l1;
      QS[2] = l2;
      QS[3] = l3;
      QS[4] = mid;
      QS[5] = r1;
      QS[6] = r2;
      QS[7] = r3;
      QS[8] = b4;
      QS[9] = margin * (1 + 2 * MARGIN_PER_LEVEL);
      if ((okL || quarters(0, sLo)) && (okR || quarters(4, sLo))) return true;
    }
  }
  Q[0] = c0;
  Q[1] = c1;
  Q[2] = c2;
  Q[3] = c3;
  Q[4] = c4;
  Q[5] = lo;
  Q[6] = hi;
  Q[7] = h;
  // Ends of one sign and p′'s Bernstein coefficients (differences of p's, as bernstein.ts: margin
  // 3·margin) with exactly one certified sign change: p has exactly one critical point in
  // [lo, lo + h], where it is smallest (or largest). The derivative splitting then needs one
  // critical point and at most two roots, with no subdivision (the common near miss).
  if (sameEnds) {
    const d0 = e1;
    const d1 = e1 + e2;
    const d2 = e1 + 2 * e2 + e3;
    const d3 = e1 + 3 * e2 + 3 * e3 + e4;
    const dm = 3 * margin;
    if (Math.min(Math.abs(d0), Math.abs(d1), Math.abs(d2), Math.abs(d3)) > dm) {
      const k01 = d0 < 0 !== d1 < 0;
      const k12 = d1 < 0 !== d2 < 0;
      const k23 = d2 < 0 !== d3 < 0;
      if ((k01 ? 1 : 0) + (k12 ? 1 : 0) + (k23 ? 1 : 0) === 1) {
        // Start: where p′'s control polygon crosses zero.
        const g = k01 ? d0 / (d0 - d1) : k12 ? 1 + d1 / (d1 - d2) : 2 + d2 / (d2 - d3);
        H[4] = lo + (h * g) / 3;
        BC[0] = b0;
        curCoeffs = coeffs;
        loaded = false;
        const r = unimodal(sLo);
        if (r > 0) return true;
        if (r < 0) return false;
        nFound = zeroAtLo ? 1 : 0; // (nothing was added)
      }
    }
  }
  BC[0] = b0;
  BC[1] = b1;
  BC[2] = b2;
  BC[3] = b3;
  BC[4] = b4;
  BC[5] = margin;
  loSign = sLo;
  const nOnes = isolate();
  if (nOnes === 0) return true;
  if (nOnes < 0) return false;
  curCoeffs = coeffs;
  loaded = false;
  if (solveOnes(nOnes)) return true;
  nFound = 0;
  return false;
}

/**
 * p has exactly one critical point in [lo, lo + h] and the exact sign s0 at lo, or just after lo
 * when p(lo) = 0 (and at lo + h; BC[0] = p(lo)): the critical point x* by safeguarded Halley on p′
 * over [lo, hi] from H[4] (when p′ changes sign there), then the exact sign of p at x* (plain
 * Horner with its bound): p is monotone on [lo, x*] and [x*, lo + h], so p keeping the sign s0 at
 * x* means no root; else one root in (lo, x*) and one in (x*, hi) when p(hi) has the sign s0
 * again, each solved as a one-root piece. Returns 1 when done; 0 when p′(lo), p′(hi) do not change
 * sign or p dips after a zero at lo (the caller subdivides instead); −1 when p(x*) is at
 * rounding-noise level or p(hi) = 0 (the general path, with its exact repair around noisy
 * critical points, decides).
 */
function unimodal(s0: number): number {
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
  const sx = signPlain(xs);
  if (sx === 0) return -1;
  // p keeps the sign s0 at its only extremum: no root (p(lo + h) has the sign s0 too, and p is
  // monotone from x* to there, so p(hi) has it).
  if (sx === s0) return 1;
  if (zeroAtLo) return 0; // p(lo) = 0 and a dip: subdivision brackets the roots after lo
  const ax = absAt[0] as number;
  const sh = signAt(hi, 1);
  if (sh === 0) return -1;
  const ah = absAt[1] as number;
  // One root in (lo, x*), and one in (x*, hi) unless it lies beyond hi.
  if (!rootIn(lo, xs, s0, Math.abs(BC[0] as number), ax, 2)) return -1;
  if (sh !== sx && !rootIn(xs, hi, sx, ax, ah, 1)) return -1;
  return 1;
}

/** Exact sign of p at x when plain Horner with its bound decides it (|p(x)| into absAt[0]), else 0. */
function signPlain(x: number): number {
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
  absAt[0] = av;
  return av > B4 * a && a >= TINY_SCALE ? (v > 0 ? 1 : -1) : 0;
}

/**
 * The root in (a, b) where p's exact signs are sa at a and −sa at b (|p| there fa, fb): Halley
 * (critical: bit 1 = a, bit 2 = b is a critical point, for the start), then refine. False when the
 * bracket's ends round together.
 */
function rootIn(a: number, b: number, sa: number, fa: number, fb: number, critical: number): boolean {
  if (!(a < b)) return false;
  H[0] = a;
  H[1] = b;
  H[2] = sa * (fa > 0 ? fa : 1);
  H[3] = -sa * (fb > 0 ? fb : 1);
  H[4] = Number.NaN;
  halley(0, critical);
  H[0] = a;
  H[1] = b;
  H[2] = fa;
  H[3] = fb;
  H[4] = H[5] as number;
  pushRoot(refined(sa));
  return true;
}

/**
 * Subdivision of BC: records the one-root pieces in `ones`, left to right; returns their number,
 * or −1 when a piece end is at noise level or MAX_DEPTH is reached undecided.
 */
function isolate(): number {
  const margin = BC[5] as number;
  let b0 = BC[0] as number;
  let b1 = BC[1] as number;
  let b2 = BC[2] as number;
  let b3 = BC[3] as number;
  let b4 = BC[4] as number;
  let sp = 0;
  let nOnes = 0;
  let s = 0;
  let depth = 0;
  let w = 1;
  for (;;) {
    const m = margin * (1 + MARGIN_PER_LEVEL * depth);
    // One sign beyond the margin: no root (the common leaf). Else, with certified ends of
    // opposite signs and certain interior signs, count the sign changes (odd: 1 or 3).
    // The sign of the piece's left end: certified by the margin, or exact at lo (loSign).
    const sl = s === 0 ? loSign : b0 > m ? 1 : b0 < -m ? -1 : 0;
    let leaf = sl > 0 ? Math.min(b1, b2, b3, b4) > m : sl < 0 && Math.max(b1, b2, b3, b4) < -m;
    let changes = 0;
    if (!leaf) {
      if (sl === 0 || !(Math.abs(b4) > m)) return -1; // a piece end at noise level
      const n0 = sl < 0;
      if (n0 !== b4 < 0 && Math.abs(b1) > m && Math.abs(b2) > m && Math.abs(b3) > m) {
        changes = (n0 !== b1 < 0 ? 1 : 0) + (b1 < 0 !== b2 < 0 ? 1 : 0) + (b2 < 0 !== b3 < 0 ? 1 : 0);
        changes += b3 < 0 !== b4 < 0 ? 1 : 0;
        leaf = changes === 1;
      }
    }
    if (!leaf) {
      if (depth >= MAX_DEPTH) return -1;
      // de Casteljau at the middle: push the right half, continue with the left.
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
      depth++;
      w *= 0.5;
      const e = 8 * sp++;
      stack[e] = mid;
      stack[e + 1] = r1;
      stack[e + 2] = r2;
      stack[e + 3] = r3;
      stack[e + 4] = b4;
      stack[e + 5] = s + w;
      stack[e + 6] = depth;
      stack[e + 7] = w;
      b1 = l1;
      b2 = l2;
      b3 = l3;
      b4 = mid;
      continue;
    }
    if (changes === 1) {
      // Exactly one simple root: the piece, and where its control polygon crosses zero.
      let g: number;
      if (sl < 0 !== b1 < 0) g = b0 / (b0 - b1);
      else if (b1 < 0 !== b2 < 0) g = 1 + b1 / (b1 - b2);
      else if (b2 < 0 !== b3 < 0) g = 2 + b2 / (b2 - b3);
      else g = 3 + b3 / (b3 - b4);
      const o = 4 * nOnes++;
      ones[o] = s;
      ones[o + 1] = s + w;
      ones[o + 2] = s + 0.25 * w * g;
      ones[o + 3] = sl;
    }
    if (sp === 0) return nOnes;
    const e = 8 * --sp;
    b0 = stack[e] as number;
    b1 = stack[e + 1] as number;
    b2 = stack[e + 2] as number;
    b3 = stack[e + 3] as number;
    b4 = stack[e + 4] as number;
    s = stack[e + 5] as number;
    depth = stack[e + 6] as number;
    w = stack[e + 7] as number;
  }
}

/**
 * One certified root per one-root piece (see the module header): false on any doubt (a double end
 * whose exact sign differs from the real end's, an exact zero, ends that round together).
 */
function solveOnes(nOnes: number): boolean {
  const lo = Q[5] as number;
  const hi = Q[6] as number;
  const h = Q[7] as number;
  for (let k = 0; k < nOnes; k++) {
    const o = 4 * k;
    const sl = ones[o] as number;
    const sr = ones[o + 1] as number;
    const sg = ones[o + 3] as number;
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
    const fa = absAt[0] as number;
    const fb = absAt[1] as number;
    H[0] = a;
    H[1] = b;
    H[2] = sg * fa;
    H[3] = sb * fb;
    H[4] = lo + (ones[o + 2] as number) * h;
    halley(0, 0);
    H[0] = a;
    H[1] = b;
    H[2] = fa;
    H[3] = fb;
    H[4] = H[5] as number;
    pushRoot(refined(sg));
  }
  return true;
}

/** Exact sign of p (registers Q) at x; |p(x)| into absAt[slot]. */
function signAt(x: number, slot: number): number {
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
  if (av > B4 * a && a >= TINY_SCALE) {
    absAt[slot] = av;
    return v > 0 ? 1 : -1;
  }
  ensureLoaded();
  const sg = certSign(x);
  absAt[slot] = lastAbsValue();
  return sg;
}

/**
 * newtonPlain (newton.ts) on p (registers Q) over the bracket H[0..1] with plain values H[2..3] of
 * opposite signs, started from H[4] when inside (else regula falsi): the same steps, safeguards and
 * stopping rule; the result into H[5]. Throws RootSolverError after ROOTS_MAX_ITERATIONS steps.
 */
function halley(off: number, critical: number): void {
  const c0 = Q[off] as number;
  const c1 = Q[off + 1] as number;
  const c2 = Q[off + 2] as number;
  const c3 = Q[off + 3] as number;
  const c4 = Q[off + 4] as number;
  let a = H[0] as number;
  let b = H[1] as number;
  const fa = H[2] as number;
  const fb = H[3] as number;
  const guess = H[4] as number;
  const aNeg = fa < 0;
  let x = guess;
  if (!(x > a && x < b) && critical !== 0) {
    // newton.ts's start at a critical end e (p′(e) = 0): p(e + δ) ≈ p(e) + p″(e)δ²/2.
    const e = critical === 1 ? a : b;
    let f = c4 * e + c3;
    let d1 = c4 * e + f;
    let d2 = c4;
    f = f * e + c2;
    d2 = d2 * e + d1;
    d1 = d1 * e + f;
    d2 = d2 * e + d1;
    const q = -(critical === 1 ? fa : fb) / d2;
    if (q > 0) x = critical === 1 ? a + Math.sqrt(q) : b - Math.sqrt(q);
  }
  if (!(x > a && x < b)) x = a - fa * ((b - a) / (fb - fa));
  if (!(x > a && x < b)) x = splitPoint(a, b);
  let dxOld = Number.POSITIVE_INFINITY;
  let dx = Number.POSITIVE_INFINITY;
  for (let it = 0; it < MAX_IT; it++) {
    // p, p′ and p″/2 at x in one Horner pass (newtonPlain's loop unrolled; the first line is the
    // x³ step, after which p″/2 = c4 and p′ = c4·x + (c4·x + c3)).
    let f = c4 * x + c3;
    let d1 = c4 * x + f;
    let d2 = c4;
    f = f * x + c2;
    d2 = d2 * x + d1;
    d1 = d1 * x + f;
    f = f * x + c1;
    d2 = d2 * x + d1;
    d1 = d1 * x + f;
    f = f * x + c0;
    if (f === 0) {
      H[5] = x;
      return;
    }
    if (f < 0 === aNeg) a = x;
    else b = x;
    // Halley's step where it is a small correction of Newton's, Newton's elsewhere (newton.ts).
    const fd2 = f * d2;
    const d11 = d1 * d1;
    const hal = Math.abs(fd2) <= 0.5 * d11;
    const step = hal && it < NEWTON_STEPS ? (f * d1) / (d11 - fd2) : f / d1;
    const as = Math.abs(step);
    const ax = Math.abs(x);
    let xn = x - step;
    if (hal && Math.abs(f) <= EARLY * ax * Math.abs(d1) && xn >= a && xn <= b) {
      H[5] = xn;
      return;
    }
    if (it >= NEWTON_STEPS || !(xn > a && xn < b) || as > 0.5 * Math.abs(dxOld)) {
      xn = splitPoint(a, b);
      if (xn === a) {
        H[5] = x;
        return;
      }
    }
    dxOld = dx;
    dx = xn - x;
    x = xn;
  }
  throw new RootSolverError(`newton: no convergence in ${MAX_IT} iterations on [${a}, ${b}]`);
}

/**
 * certify.ts's refineRoot for p (registers Q) in scalar arithmetic, for the common case: H[0..1] =
 * bracket a < b with exact signs sa at a and −sa at b, H[2..3] = |p| there, H[4] = the start x0
 * (inside). One compensated Horner evaluation at x0 (as compHorner: value, rigorous bound, p′(x0),
 * p̃′(|x0|), p̃″(|x0|)/2) decides its exact sign; then the certified local model walks ulp by ulp
 * to two adjacent doubles (as refineRoot). Returns true with the root in H[5]; false when the
 * compensated sign is uncertain, underflow is near or the model cannot decide: H[0..4] then hold
 * the (narrowed) bracket, its |p| and a start for refineRoot, which finishes with full
 * evaluations (exact fallback included).
 */
function refine(sa: number): boolean {
  let a = H[0] as number;
  let b = H[1] as number;
  let absA = H[2] as number;
  let absB = H[3] as number;
  const x = H[4] as number;
  if (!(x > a && x < b)) return false;
  // Compensated Horner (compHorner.ts, degree 4, unrolled): s + r the value, e the sum of the
  // |error terms|, pmin the smallest |product| (underflow check), d = p′, a1 = p̃′, a2 = p̃″/2.
  const c0 = Q[0] as number;
  const c1 = Q[1] as number;
  const c2 = Q[2] as number;
  const c3 = Q[3] as number;
  const c4 = Q[4] as number;
  let t = SPLIT * x;
  const xh = t - (t - x);
  const xl = x - xh;
  const ax = Math.abs(x);
  const xm = Math.max(ax, 1);
  let s = c4;
  let aa = Math.abs(c4);
  let pmin: number;
  // x^3 step
  let d = c4;
  let a2 = 0;
  let a1 = aa;
  let p = s * x;
  t = SPLIT * s;
  let sh = t - (t - s);
  let sl = s - sh;
  let pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
  s = p + c3;
  let z = s - p;
  let q = pe + (p - (s - z) + (c3 - z));
  let r = q;
  let e = Math.abs(q);
  pmin = Math.abs(p);
  aa = aa * ax + Math.abs(c3);
  // x^2 step
  d = d * x + s;
  a2 = a2 * ax + a1;
  a1 = a1 * ax + aa;
  p = s * x;
  t = SPLIT * s;
  sh = t - (t - s);
  sl = s - sh;
  pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
  s = p + c2;
  z = s - p;
  q = pe + (p - (s - z) + (c2 - z));
  r = r * x + q;
  e += Math.abs(q);
  pmin = Math.min(pmin, Math.abs(p));
  aa = aa * ax + Math.abs(c2);
  // x^1 step
  d = d * x + s;
  a2 = a2 * ax + a1;
  a1 = a1 * ax + aa;
  p = s * x;
  t = SPLIT * s;
  sh = t - (t - s);
  sl = s - sh;
  pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
  s = p + c1;
  z = s - p;
  q = pe + (p - (s - z) + (c1 - z));
  r = r * x + q;
  e += Math.abs(q);
  pmin = Math.min(pmin, Math.abs(p));
  aa = aa * ax + Math.abs(c1);
  // x^0 step
  d = d * x + s;
  a2 = a2 * ax + a1;
  a1 = a1 * ax + aa;
  p = s * x;
  t = SPLIT * s;
  sh = t - (t - s);
  sl = s - sh;
  pe = sl * xl - (p - sh * xh - sl * xh - sh * xl);
  s = p + c0;
  z = s - p;
  q = pe + (p - (s - z) + (c0 - z));
  r = r * x + q;
  e += Math.abs(q);
  pmin = Math.min(pmin, Math.abs(p));
  aa = aa * ax + Math.abs(c0);
  const v = s + r;
  const av = Math.abs(v);
  const xm2 = xm * xm;
  const pw = xm2 * xm2;
  let bound = 0;
  if (e !== 0 || !(pmin >= UNDERFLOW)) {
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
  } else {
    b = x;
    absB = av;
  }
  // The certified local model p(x + h) ∈ v + d·h ± (bound + |h|·e1 + a2·h² + u|·|), as refineRoot.
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
      const hm = Math.max(Math.abs(hu), Math.abs(hd));
      // One error bound for the three points (the largest |h|, the largest |m|).
      const err = SAFETY * (bound + hm * e1 + a2 * hm * hm + U * Math.max(am0, amu, amd));
      if (hm <= span && am0 > err) {
        const s0 = m0 > 0 ? 1 : -1;
        if (s0 === sa) {
          // p(y) has a's sign: the root is above y.
          if (amu > err && (mu > 0 ? 1 : -1) !== sa && yu <= b) {
            H[5] = am0 <= amu ? y : yu;
            return true;
          }
        } else if (amd > err && (md > 0 ? 1 : -1) === sa && yd >= a) {
          H[5] = amd <= am0 ? yd : y;
          return true;
        }
      }
    }
    // (With a and b adjacent no y lies strictly between them: the common case above cannot apply.)
    if (nextUp(a) >= b) {
      H[5] = absA <= absB ? a : b;
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
      if ((m > 0 ? 1 : -1) === sa) {
        a = y;
        absA = am;
        if (nextUp(a) >= b) {
          H[5] = absA <= absB ? a : b;
          return true;
        }
        y = nextUp(y);
      } else {
        b = y;
        absB = am;
        if (nextUp(a) >= b) {
          H[5] = absA <= absB ? a : b;
          return true;
        }
        y = nextDown(y);
      }
    }
  }
  H[0] = a;
  H[1] = b;
  H[2] = absA;
  H[3] = absB;
  H[4] = y;
  return false;
}

const f64 = new Float64Array(1);
const u32 = new Uint32Array(f64.buffer);
/** Index of the high 32 bits of a double in u32 (1 on little-endian platforms). */
const HI = (() => {
  f64[0] = 1;
  return u32[1] === 0x3ff00000 ? 1 : 0;
})();
const LO = 1 - HI;

/**
 * The adjacent double above a finite x. For 2^-960 ≤ |x| < 2^1023 it is x + |x|·(2^-53 + 2^-105)
 * in round-to-nearest (the addend lies strictly between half an ulp and 1.5 ulps of x, also at
 * binade ends; checked against the bit version in quartic.test.ts); else the bit version.
 */
export function nextUp(x: number): number {
  const ax = Math.abs(x);
  return ax >= NEXT_MIN && ax < NEXT_MAX ? x + ax * NEXT : nextUpBits(x);
}

/** The adjacent double below a finite x (as nextUp). */
export function nextDown(x: number): number {
  const ax = Math.abs(x);
  return ax >= NEXT_MIN && ax < NEXT_MAX ? x - ax * NEXT : -nextUpBits(-x);
}

const NEXT = 2 ** -53 + 2 ** -105;
const NEXT_MIN = 2 ** -960;
const NEXT_MAX = 2 ** 1023;

/** The adjacent double above a finite x from its bit pattern (exactPoly.ts's nextUp). */
function nextUpBits(x: number): number {
  if (x === 0) return Number.MIN_VALUE;
  f64[0] = x;
  let lo = u32[LO] as number;
  let hi = u32[HI] as number;
  if (x > 0) {
    lo = (lo + 1) >>> 0;
    if (lo === 0) hi = (hi + 1) >>> 0;
  } else {
    if (lo === 0) hi = (hi - 1) >>> 0;
    lo = (lo - 1) >>> 0;
  }
  u32[LO] = lo;
  u32[HI] = hi;
  return f64[0] as number;
}

/**
 * The caller's coefficients, loaded into certify.ts only when an exact sign or refineRoot is needed
 * (most calls never need them).
 */
let curCoeffs: ArrayLike<number> = Q;
let loaded = false;

function ensureLoaded(): void {
  if (!loaded) {
    load(Q, 4, curCoeffs, 0);
    loaded = true;
  }
}

/** The root bracketed in H (see refine): refine, else refineRoot from where refine stopped. */
function refined(sa: number): number {
  if (refine(sa)) return H[5] as number;
  ensureLoaded();
  return refineRoot(H[0] as number, H[1] as number, sa, H[2] as number, H[3] as number, H[4] as number);
}

/** Scratch of the second halving: the halves' coefficients (QS[0..4], QS[4..8]) and the margin. */
const QS = new Float64Array(10);

/**
 * One de Casteljau halving of the half QS[off..off+4] (ends of the sign sg, certified): true when
 * both quarters have all coefficients of that sign beyond the margin QS[9].
 */
function quarters(off: number, sg: number): boolean {
  const b0 = QS[off] as number;
  const b1 = QS[off + 1] as number;
  const b2 = QS[off + 2] as number;
  const b3 = QS[off + 3] as number;
  const b4 = QS[off + 4] as number;
  const m = QS[9] as number;
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
  return sg > 0 ? Math.min(l1, l2, l3, mid, r1, r2, r3) > m : Math.max(l1, l2, l3, mid, r1, r2, r3) < -m;
}

/** Append x to `found` keeping it strictly increasing (−0 as +0). */
function pushRoot(x: number): void {
  if (nFound === 0 || x > (found[nFound - 1] as number)) found[nFound++] = x + 0;
}
