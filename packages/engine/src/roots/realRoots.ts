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

import { ROOTS_DEGREE_DROP } from "../tolerances.js";
import { bernstein, derivChanges, guesses } from "./bernstein.js";
import { certSign, lastAbsValue, load, refineRoot } from "./certify.js";
import { push, solveLevel0 } from "./level0.js";
import { newtonPlain, pieceRoots, quadRootsPlain } from "./newton.js";
import { exponentOf, mulPow2 } from "./pow2.js";
import { found, quarticRoots } from "./quartic.js";

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

/** 2^⌊256/n⌋: intervals with max(|lo|, |hi|) within [1/MOD_LIMIT[n], MOD_LIMIT[n]] need no variable scaling. */
const MOD_LIMIT = Array.from({ length: 65 }, (_, n) => (n === 0 ? 1 : mulPow2(1, Math.floor(256 / n))));
const BIG = 2 ** 64;
const SMALL = 2 ** -64;
let cap = 0;
let P = new Float64Array(0);
let chain = new Float64Array(0);
let bufA = new Float64Array(0);
let bufB = new Float64Array(0);

function ensure(n: number): void {
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

/** A value as a message shows it: a string quoted (so "1" does not read as the number 1), with its type. */
function describe(v: unknown): string {
  return typeof v === "number"
    ? String(v)
    : `${typeof v} ${typeof v === "string" ? JSON.stringify(v) : String(v)}`;
}

/** Everything but the quartic hot path (quartic.ts); out is empty. */
function general(coeffs: ArrayLike<number>, lo: number, hi: number, out: number[]): number[] {
  const len = coeffs === null || coeffs === undefined ? undefined : coeffs.length;
  if (typeof len !== "number" || !(len >= 0 && len <= Number.MAX_SAFE_INTEGER && Math.floor(len) === len))
    throw new RangeError(
      `realRoots: coeffs must be an array-like of finite numbers, got ${describe(coeffs)}`,
    );
  if (typeof lo !== "number" || Number.isNaN(lo))
    throw new RangeError(`realRoots: lo must be a number, got ${describe(lo)}`);
  if (typeof hi !== "number" || Number.isNaN(hi))
    throw new RangeError(`realRoots: hi must be a number, got ${describe(hi)}`);
  let n = -1;
  let maxAbs = 0;
  for (let i = 0; i < len; i++) {
    const c = coeffs[i] as number;
    if (typeof c !== "number" || !(c - c === 0)) {
      throw new RangeError(`realRoots: coeffs[${i}] must be a finite number, got ${describe(c)}`);
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
  const bound = (1 + maxAbs / Math.abs(coeffs[n] as number)) * (1 + 2 ** -48);
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

/** The variable's scale exponent for an interval of magnitude M: 0 when |log2 M|·n ≤ 256, else ⌊log2 M⌋ + 1. */
function variableScale(n: number, M: number): number {
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
function solvePieces(
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
function solveRange(
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
