/**
 * The registers of the quartic hot path (quartic.ts and its step modules): module-level typed
 * arrays that carry doubles between its functions, the roots found, and the few mutable scalars.
 *
 * - `Q`: c0…c4, lo, hi, h (the Bernstein interval's width), then p′'s coefficients c1, 2c2, 3c3,
 *   4c4, 0 from `P1`.
 * - `H`: Halley's and refine's arguments and result: bracket a, b; values there (plain values of
 *   opposite signs for Halley, |p| for refine); a start; the root (see quarticHalley.ts,
 *   quarticRefine.ts).
 * - `BC`: the Bernstein coefficients b0…b4 of p on [lo, lo + h] and their margin.
 * - `absAt`: |p| at the last two certified sign evaluations (quarticSigns.ts).
 * - `found` / `state.nFound`: the roots of the current call, ascending (`pushRoot`).
 * - `state.coeffs` / `state.loaded`: the caller's coefficients, loaded into certify.ts only when an
 *   exact sign or refineRoot is needed (`ensureLoaded`; most calls never need them).
 *
 * Speed (V8): doubles pass through these arrays, never as arguments or results of calls V8 does not
 * inline (it boxes those). Each module that uses a register binds it to a module-local const
 * (`const Q = reg.Q`): V8 folds a module's own consts into its optimised code (typed array length
 * and data known, no bounds checks on constant slots), while each use of an import is a load and a
 * check. (Split with imported registers, this path measured +9% instructions; see quartic.ts.)
 */

import { load } from "./certify.js";

// (Exported bindings are module cells even inside their own module: the functions below use
// the unexported consts.)
const q = new Float64Array(13);
const roots = new Float64Array(8);
const st = {
  /** Number of roots in `found`. */
  nFound: 0,
  /** p(lo) = 0 exactly (already reported); the signs used are those of p just after lo. */
  zeroAtLo: false,
  coeffs: q as ArrayLike<number>,
  loaded: false,
};

export const Q: Float64Array = q;
/** Offset of p′'s coefficients in Q. */
export const P1 = 8;
export const H: Float64Array = new Float64Array(6);
export const BC: Float64Array = new Float64Array(6);
export const absAt: Float64Array = new Float64Array(2);
/** The roots found by the last quarticRoots call (found[0..count)), ascending. */
export const found: Float64Array = roots;
export const state = st;

/** The caller's coefficients for this call (loaded into certify.ts only if needed). */
export function useCoeffs(coeffs: ArrayLike<number>): void {
  st.coeffs = coeffs;
  st.loaded = false;
}

/** Loads Q's coefficients (and the caller's originals) into certify.ts, once per call. */
export function ensureLoaded(): void {
  if (!st.loaded) {
    load(q, 4, st.coeffs, 0);
    st.loaded = true;
  }
}

/** Append x to `found` keeping it strictly increasing (−0 as +0). */
export function pushRoot(x: number): void {
  const n = st.nFound;
  if (n === 0 || x > (roots[n - 1] as number)) {
    roots[n] = x + 0;
    st.nFound = n + 1;
  }
}
