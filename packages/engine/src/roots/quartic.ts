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
 *    the issue with a single split point (quarticPieces.ts's unimodal; its "no root" is certified
 *    over an interval proven to hold the critical point, keepsSign, not read at an estimate of it).
 * 5. Otherwise, Bernstein subdivision (quarticIsolate.ts), each one-root piece solved by
 *    quarticPieces.ts's solveOnes.
 * Each root: safeguarded Halley in its bracket (quarticHalley.ts), then one compensated Horner
 * evaluation and certify.ts's certified local model decide the two doubles around it
 * (quarticRefine.ts; refineRoot finishes the rare undecided cases, exact fallback included).
 * Loops are bounded (ROOTS_MAX_ITERATIONS, MAX_DEPTH); RootSolverError as newton.ts.
 *
 * Speed notes (V8; measurements in README.md, Speed): doubles pass between the hot path's modules
 * through the typed arrays of quarticRegisters.ts, never as arguments or results of calls V8 does
 * not inline (it boxes those); each module binds the registers and imported constants to
 * module-local consts (an import is a load and a check at every use). The de Casteljau halving is
 * written out here, in quarticSigns.ts's quarters and in quarticIsolate.ts rather than shared, and
 * `settle` stays one function, because sharing and splitting measured more.
 */

import { ROOTS_CAUCHY_WIDENING, ROOTS_SUBDIVISION_MARGIN_GROWTH, UNIT_ROUNDOFF } from "../tolerances.js";
import { certSign } from "./certify.js";
import { isolate } from "./quarticIsolate.js";
import { solveOnes, unimodal } from "./quarticPieces.js";
import * as reg from "./quarticRegisters.js";
import { QS as QS_, quarters } from "./quarticSigns.js";

/** Cauchy's bound widened (tolerances.ts ROOTS_CAUCHY_WIDENING): a module constant on the hot path. */
const CAUCHY_WIDENED = 1 + ROOTS_CAUCHY_WIDENING;

export { found } from "./quarticRegisters.js";

const U = UNIT_ROUNDOFF;
/** Coefficient magnitudes and interval ends realRoots uses unscaled (as realRoots.ts). */
const SMALL = 2 ** -64;
const BIG = 2 ** 64;
/** 1/C(4,2), rounded (the margin covers it, as bernstein.ts's 1/C(n,k)). */
const SIXTH = 1 / 6;
/** Module-local copies (V8 folds a module's own consts, not imports; see quarticRegisters.ts). */
const MARGIN_PER_LEVEL = ROOTS_SUBDIVISION_MARGIN_GROWTH;
const Q = reg.Q;
const H = reg.H;
const BC = reg.BC;
const QS = QS_;
const state = reg.state;
/** The Taylor shifts of p and |p| (when lo ≠ 0). */
const TS = new Float64Array(8);

export function quarticRoots(coeffs: ArrayLike<number>, lo: number, hi: number): number {
  state.nFound = 0;
  return settle(coeffs, lo, hi) ? state.nFound : -1;
}

/** Taylor shift of a0 + a1 t + … + a4 t⁴ to x (Horner's scheme): the new a0…a3 into TS[o..o+4]. */
function shift(a0: number, a1: number, a2: number, a3: number, a4: number, x: number, o: number): void {
  let t0 = a0;
  let t1 = a1;
  let t2 = a2;
  let t3 = a3;
  t3 += x * a4;
  t2 += x * t3;
  t1 += x * t2;
  t0 += x * t1;
  t3 += x * a4;
  t2 += x * t3;
  t1 += x * t2;
  t3 += x * a4;
  t2 += x * t3;
  t3 += x * a4;
  TS[o] = t0;
  TS[o + 1] = t1;
  TS[o + 2] = t2;
  TS[o + 3] = t3;
}

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
  // (Written with & on the comparisons: one branch, not one per sign, which would mispredict.)
  if (
    lo >= 0 &&
    (c0 > 0
      ? (+(c1 >= 0) & +(c2 >= 0) & +(c3 >= 0) & +(c4 >= 0)) !== 0
      : c0 < 0 && (+(c1 <= 0) & +(c2 <= 0) & +(c3 <= 0) & +(c4 <= 0)) !== 0)
  ) {
    return true;
  }
  const a0 = Math.abs(c0);
  const a1 = Math.abs(c1);
  const a2 = Math.abs(c2);
  const a3 = Math.abs(c3);
  const a4 = Math.abs(c4);
  // (Comparison chains, not Math.min/max: V8 compiles those to data-dependent branches.)
  if (
    !(
      (a0 >= SMALL || a1 >= SMALL || a2 >= SMALL || a3 >= SMALL || a4 >= SMALL) &&
      a0 <= BIG &&
      a1 <= BIG &&
      a2 <= BIG &&
      a3 <= BIG &&
      a4 <= BIG
    )
  )
    return false;
  // Cauchy's bound, as realRoots: every root has |t| < 1 + max|c_i| / |c4|. (No division unless
  // an end may lie beyond it: |x|·|c4| ≤ maxAbs, computed, gives |x| < the bound.)
  // biome-ignore lint/complexity/useMathMinMax: Math.max compiles to data-dependent branches in V8
  const far = (hi > -lo ? hi : -lo) * a4;
  if (far > a0 && far > a1 && far > a2 && far > a3 && far > a4) {
    const maxAbs = Math.max(a0, a1, a2, a3, a4);
    const bound = (1 + maxAbs / a4) * CAUCHY_WIDENED;
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
    shift(c0, c1, c2, c3, c4, lo, 0);
    shift(a0, a1, a2, a3, a4, Math.abs(lo), 4);
    t0 = TS[0] as number;
    t1 = TS[1] as number;
    t2 = TS[2] as number;
    t3 = TS[3] as number;
    s0 = TS[4] as number;
    s1 = TS[5] as number;
    s2 = TS[6] as number;
    s3 = TS[7] as number;
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
  // Depth 0 (most calls end here): every coefficient of one sign, no root. (& as above.)
  if (
    b0 > margin
      ? (+(b1 > margin) & +(b2 > margin) & +(b3 > margin) & +(b4 > margin)) !== 0
      : b0 < -margin && (+(b1 < -margin) & +(b2 < -margin) & +(b3 < -margin) & +(b4 < -margin)) !== 0
  )
    return true;
  // The exact sign of p(lo) = b0: certified by the margin, else (p(lo) at rounding-noise level:
  // touching discs) decided exactly; p(lo) = 0 goes to the general path.
  let sLo = b0 > margin ? 1 : b0 < -margin ? -1 : 0;
  let zeroAtLo = false;
  Q[0] = c0;
  Q[1] = c1;
  Q[2] = c2;
  Q[3] = c3;
  Q[4] = c4;
  if (sLo === 0) {
    reg.useCoeffs(coeffs);
    reg.ensureLoaded();
    sLo = certSign(lo);
    if (sLo === 0) {
      // p(lo) = 0 exactly (discs touching at lo): the Bernstein coefficients of p(t)/(t − lo) on
      // the same interval are (4/j)·b_j, j ≥ 1, so b1…b4 of one sign leave lo as the only root.
      reg.pushRoot(lo);
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
    // (Written out, as in quarters and isolate: see the header.)
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
    const okL = sLo > 0 ? l1 > m && l2 > m && l3 > m && mid > m : l1 < -m && l2 < -m && l3 < -m && mid < -m;
    const okR = sLo > 0 ? mid > m && r1 > m && r2 > m && r3 > m : mid < -m && r1 < -m && r2 < -m && r3 < -m;
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
    if (Math.abs(d0) > dm && Math.abs(d1) > dm && Math.abs(d2) > dm && Math.abs(d3) > dm) {
      const k01 = d0 < 0 !== d1 < 0;
      const k12 = d1 < 0 !== d2 < 0;
      const k23 = d2 < 0 !== d3 < 0;
      if ((k01 ? 1 : 0) + (k12 ? 1 : 0) + (k23 ? 1 : 0) === 1) {
        // Start: where p′'s control polygon crosses zero.
        const g = k01 ? d0 / (d0 - d1) : k12 ? 1 + d1 / (d1 - d2) : 2 + d2 / (d2 - d3);
        H[4] = lo + (h * g) / 3;
        BC[0] = b0;
        reg.useCoeffs(coeffs);
        const r = unimodal(sLo, zeroAtLo);
        if (r > 0) return true;
        if (r < 0) return false;
        state.nFound = zeroAtLo ? 1 : 0; // (nothing was added)
      }
    }
  }
  BC[0] = b0;
  BC[1] = b1;
  BC[2] = b2;
  BC[3] = b3;
  BC[4] = b4;
  BC[5] = margin;
  const nOnes = isolate(sLo);
  if (nOnes === 0) return true;
  if (nOnes < 0) return false;
  reg.useCoeffs(coeffs);
  if (solveOnes(nOnes, zeroAtLo)) return true;
  state.nFound = 0;
  return false;
}
