/**
 * The general solve of realRoots (realRoots.ts) once the input is checked and the interval clamped:
 * exact power-of-two scaling of the coefficients and, for extreme intervals, of the variable
 * (variableScale, solveRange; an interval reaching from near 0 far beyond 1 in pieces of one
 * variable scaling each, solvePieces), the scale-aware degree drop (ROOTS_DEGREE_DROP), the Bernstein
 * sign checks, the critical points that split [lo, hi] into monotone pieces (found recursively down
 * to a closed-form quadratic), and the certified solve of each piece (level0.ts, certify.ts). The
 * method and its accuracy are described in realRoots.ts and README.md. Not re-entrant: module
 * scratch buffers, grown by ensure(n) before a solve of degree n.
 */

import { ROOTS_DEGREE_DROP } from "../tolerances.js";
import { bernstein, derivChanges, guesses } from "./bernstein.js";
import { certSign, lastAbsValue, load, refineRoot } from "./certify.js";
import { push, solveLevel0 } from "./level0.js";
import { newtonPlain, pieceRoots, quadRootsPlain } from "./newton.js";
import { exponentOf, mulPow2 } from "./pow2.js";

/** 2^⌊256/n⌋: intervals with max(|lo|, |hi|) within [1/MOD_LIMIT[n], MOD_LIMIT[n]] need no variable scaling. */
const MOD_LIMIT = Array.from({ length: 65 }, (_, n) => (n === 0 ? 1 : mulPow2(1, Math.floor(256 / n))));
const BIG = 2 ** 64;
const SMALL = 2 ** -64;
let cap = 0;
let P = new Float64Array(0);
let chain = new Float64Array(0);
let bufA = new Float64Array(0);
let bufB = new Float64Array(0);

/** Grows the scratch buffers to hold a polynomial of degree n. */
export function ensure(n: number): void {
  if (n <= cap) return;
  cap = n;
  P = new Float64Array(n + 1);
  chain = new Float64Array((n + 1) * (n + 1));
  bufA = new Float64Array(n + 1);
  bufB = new Float64Array(n + 1);
}

/**
 * p′ has exactly one simple root in (lo, lo + h) (Bernstein count): find it directly when p′(lo) and
 * p′(hi) have opposite signs (it is then inside (lo, hi)); otherwise the full recursion decides.
 * Result in bufA[0]; returns the number of critical points.
 */
function oneCriticalPoint(n: number, lo: number, hi: number): number {
  for (let i = 0; i < n; i++) chain[i] = (i + 1) * (P[i + 1] as number);
  let fa = chain[n - 1] as number;
  let fb = fa;
  for (let i = n - 2; i >= 0; i--) {
    fa = fa * lo + (chain[i] as number);
    fb = fb * hi + (chain[i] as number);
  }
  if (fa === 0 || fb === 0 || fa < 0 === fb < 0) return criticalPoints(n, lo, hi);
  bufA[0] = newtonPlain(chain, 0, n - 1, lo, hi, fa, fb, 0, guesses[1] as number);
  return 1;
}

/** Interior roots of the derivative of P[0..m] (m ≥ 2) in (lo, hi), sorted, into bufA; count. */
function criticalPoints(m: number, lo: number, hi: number): number {
  if (m === 2) {
    const v = -(P[1] as number) / (2 * (P[2] as number));
    if (v > lo && v < hi) {
      bufA[0] = v;
      return 1;
    }
    return 0;
  }
  const w = m + 1;
  for (let i = 0; i <= m; i++) chain[i] = P[i] as number;
  for (let L = 1; L <= m - 2; L++) {
    const src = (L - 1) * w;
    const dst = L * w;
    for (let i = 0; i <= m - L; i++) chain[dst + i] = (i + 1) * (chain[src + i + 1] as number);
  }
  const q = (m - 2) * w;
  let k = quadRootsPlain(chain[q] as number, chain[q + 1] as number, chain[q + 2] as number, lo, hi, bufA, 0);
  for (let L = m - 3; L >= 1; L--) {
    k = pieceRoots(chain, L * w, m - L, lo, hi, bufA, k, bufB);
    const t = bufA;
    bufA = bufB;
    bufB = t;
  }
  return k;
}

/** The variable's scale exponent for an interval of magnitude M: 0 when |log2 M|·n ≤ 256, else ⌊log2 M⌋ + 1. */
export function variableScale(n: number, M: number): number {
  // Fast test first (|log2 M|·n ≤ 256 ⇐ 2^(-256/n) ≤ M ≤ 2^(256/n)); exponents only when it fails.
  const lim = n < MOD_LIMIT.length ? (MOD_LIMIT[n] as number) : 1;
  if (M <= lim && (M >= 1 / lim || M === 0)) return 0;
  const eM = M > 0 && M < Number.POSITIVE_INFINITY ? exponentOf(M) : 0;
  return n * Math.abs(eM) > 256 ? eM + 1 : 0;
}

/** Roots of one piece, scaled back (solvePieces). */
const pieceOut: number[] = [];

/**
 * An interval reaching far beyond 1 in magnitude from near 0 (an infinite end clamped to a large
 * Cauchy bound): solved in pieces, each within one variable scaling, ascending: |t| ≤ 2^W (W =
 * ⌊256/n⌋, no variable scaling, as a moderate interval), then 2^(W + k·w) ≤ |t| ≤ 2^(W + (k+1)·w)
 * (w = max(W, 1)), where the scaled variable stays within [2^-(w+1), 1] and every term that matters
 * there stays normal. Adjacent pieces share their end, so that no sign change falls between them;
 * a root at a shared end is reported once.
 */
export function solvePieces(
  coeffs: ArrayLike<number>,
  n: number,
  maxAbs: number,
  lo: number,
  hi: number,
  out: number[],
): void {
  const W = Math.floor(256 / n);
  const w = W > 0 ? W : 1;
  const M = Math.max(-lo, hi);
  let top = W;
  while (mulPow2(1, top) < M) top += w;
  for (let e = top; e > W; e -= w)
    solvePiece(coeffs, n, maxAbs, Math.max(lo, -mulPow2(1, e)), Math.min(hi, -mulPow2(1, e - w)), out);
  solvePiece(coeffs, n, maxAbs, Math.max(lo, -mulPow2(1, W)), Math.min(hi, mulPow2(1, W)), out);
  for (let e = W + w; e <= top; e += w)
    solvePiece(coeffs, n, maxAbs, Math.max(lo, mulPow2(1, e - w)), Math.min(hi, mulPow2(1, e)), out);
}

/** One piece of solvePieces: its roots appended to out, above the last one there. */
function solvePiece(
  coeffs: ArrayLike<number>,
  n: number,
  maxAbs: number,
  lo: number,
  hi: number,
  out: number[],
): void {
  if (lo > hi) return;
  pieceOut.length = 0;
  solveRange(coeffs, n, maxAbs, lo, hi, variableScale(n, Math.max(-lo, hi, lo, -hi)), pieceOut);
  for (let i = 0; i < pieceOut.length; i++) push(out, pieceOut[i] as number);
}

/** [lo, hi] (clamped) with the variable scaled by 2^xs; appends the roots to out, which is empty. */
export function solveRange(
  coeffs: ArrayLike<number>,
  n: number,
  maxAbs: number,
  lo: number,
  hi: number,
  xs: number,
  out: number[],
): void {
  // Exact power-of-two scaling: coefficients to about 1 and, for extreme intervals, the variable
  // (t = 2^xs·s) so that |s| ≤ 1; the roots are unchanged (up to that exact factor).
  normalise(coeffs, n, maxAbs, xs);
  if (xs !== 0) {
    lo = mulPow2(lo, -xs);
    hi = mulPow2(hi, -xs);
  }
  load(P, n, coeffs, xs);
  if (lo === hi) {
    if (certSign(lo) === 0) out.push(lo);
  } else {
    solveScaled(n, lo, hi, out);
  }
  if (xs !== 0) {
    // Back to the caller's variable (exact unless the root is subnormal, where distinct scaled
    // roots can round to one double: keep them distinct).
    let k = 0;
    for (let i = 0; i < out.length; i++) {
      const r = mulPow2(out[i] as number, xs) + 0;
      if (k === 0 || r > (out[k - 1] as number)) out[k++] = r;
    }
    out.length = k;
  }
}

/**
 * Fill P with the coefficients, scaled by exact powers of two when needed: xs is the exponent of
 * the variable scaling (variableScale). Coefficients are then scaled to a largest magnitude near
 * 1, unless it is already within [2^-64, 2^64]. Coefficients more than ~2^1070 below the largest
 * underflow (documented limit).
 */
function normalise(coeffs: ArrayLike<number>, n: number, maxAbs: number, xs: number): void {
  if (xs === 0 && maxAbs >= SMALL && maxAbs <= BIG) {
    const p = P;
    for (let i = 0; i <= n; i++) p[i] = coeffs[i] as number;
    return;
  }
  let E = Number.NEGATIVE_INFINITY;
  for (let i = 0; i <= n; i++) {
    const c = coeffs[i] as number;
    if (c !== 0) E = Math.max(E, exponentOf(c) + xs * i);
  }
  for (let i = 0; i <= n; i++) P[i] = mulPow2(coeffs[i] as number, xs * i - E);
}

/** The solve proper on the normalised polynomial P (degree n) over lo < hi; appends to out. */
function solveScaled(n: number, lo: number, hi: number, out: number[]): void {
  // Degree drop: leading terms below one rounding of a lower term over the whole interval.
  const M = Math.max(-lo, hi, lo, -hi);
  let m = n;
  while (m >= 1) {
    let t = Math.abs(P[m] as number);
    let drop = false;
    for (let j = m - 1; j >= 0; j--) {
      t *= M;
      if (t < ROOTS_DEGREE_DROP * Math.abs(P[j] as number)) {
        drop = true;
        break;
      }
    }
    if (!drop) break;
    m--;
  }
  if (m === 0) return; // every other term is below u·|c0|: p keeps the sign of c0
  const v = bernstein(P, n, lo, hi, bufA, bufB);
  if (v === 0) return;
  if (v === 1) {
    // Exactly one simple root in (lo, lo + h): when p(lo) and p(hi) have opposite exact signs it is
    // inside (lo, hi) and no structure is needed (fast path); otherwise the full method decides.
    const sa = certSign(lo);
    const absLo = lastAbsValue();
    const sb = certSign(hi);
    if (sa !== 0 && sb === -sa) {
      const absHi = lastAbsValue();
      const x0 = newtonPlain(P, 0, n, lo, hi, sa * absLo, sb * absHi, 0, guesses[0] as number);
      push(out, refineRoot(lo, hi, sa, absLo, absHi, x0));
      return;
    }
  }
  let ns: number;
  if (m === n && derivChanges === 0) {
    ns = 0; // p′ keeps its sign: p is monotone on [lo, hi]
  } else if (m === n && derivChanges === 1 && n >= 2) {
    ns = oneCriticalPoint(n, lo, hi);
  } else {
    ns = m >= 2 ? criticalPoints(m, lo, hi) : 0;
  }
  solveLevel0(P, n, m, lo, hi, bufA, ns, out);
}
