/**
 * realRoots(coeffs, lo, hi): the distinct real roots of p(t) = c0 + c1 t + c2 t² + … in [lo, hi],
 * sorted ascending. Any degree; `coeffs` is any array-like of finite numbers (ascending powers).
 *
 * Method (see README.md): trim zero leading coefficients, scale by powers of two (exact), clamp
 * infinite or huge ends to Cauchy's root bound, drop leading terms negligible over the interval
 * (ROOTS_DEGREE_DROP, relative). Quick sign checks on p's Bernstein coefficients over [lo, hi]:
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
 * of the polynomial with the given double coefficients, and every exact sign change between
 * consecutive piece ends is reported. A grazing root is backward stable: an exact double root of a
 * polynomial whose coefficients differ from the given ones by at most about 2.5·n·u relatively
 * (it cannot always be within 4 ulps of an exact root: with rounded coefficients the exact
 * polynomial may have no real root there at all). Limits: coefficients spread over more than
 * ~2^1000 (scaling underflows the small ones), and evaluation overflow in the plain phases.
 *
 * Errors: a non-finite coefficient or NaN end throws RangeError naming the field; lo > hi returns [];
 * a constant (or identically zero) polynomial has no isolated roots and returns []. Iteration caps
 * throw RootSolverError (never expected). Not re-entrant (module scratch buffers).
 */

import { ROOTS_DEGREE_DROP, UNIT_ROUNDOFF } from "../tolerances.js";
import {
  certSign,
  criticalPoint,
  lastAbsValue,
  lastWasNoisy,
  load,
  nearestCritical,
  refineRoot,
} from "./certify.js";
import { newtonPlain, pieceRoots, quadRootsPlain } from "./newton.js";
import { exponentOf, mulPow2 } from "./pow2.js";

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

/** 1/C(n, k) for k = 0…n (rounded; the Bernstein test's margin covers that rounding). */
function invBinom(n: number): Float64Array {
  const r = new Float64Array(n + 1);
  let b = 1;
  for (let k = 0; k <= n; k++) {
    r[k] = 1 / b;
    b = (b * (n - k)) / (k + 1);
  }
  return r;
}
const INV_BINOM = Array.from({ length: 21 }, (_, n) => invBinom(n));
/** 2^⌊256/n⌋: intervals with max(|lo|, |hi|) within [1/MOD_LIMIT[n], MOD_LIMIT[n]] need no variable scaling. */
const MOD_LIMIT = Array.from({ length: 65 }, (_, n) => (n === 0 ? 1 : mulPow2(1, Math.floor(256 / n))));
const BIG = 2 ** 64;
const SMALL = 2 ** -64;
let cap = 0;
let P = new Float64Array(0);
let chain = new Float64Array(0);
let bufA = new Float64Array(0);
let bufB = new Float64Array(0);
let pts = new Float64Array(0);
let sgn = new Int8Array(0);
let absv = new Float64Array(0);
let noisy = new Uint8Array(0);
const crit = new Float64Array(2);
const closed = new Float64Array(2);

function ensure(n: number): void {
  if (n <= cap) return;
  cap = n;
  P = new Float64Array(n + 1);
  chain = new Float64Array((n + 1) * (n + 1));
  bufA = new Float64Array(n + 1);
  bufB = new Float64Array(n + 1);
  // Room for lo, hi, n − 1 critical points and two exact critical points beside each of them.
  pts = new Float64Array(3 * n + 3);
  sgn = new Int8Array(3 * n + 3);
  absv = new Float64Array(3 * n + 3);
  noisy = new Uint8Array(3 * n + 3);
}

/**
 * Quick sign checks with the Bernstein coefficients of p on [lo, lo + h] (h ≥ hi − lo, from a
 * Taylor shift): they bound p there (convex hull property), and their number of sign changes V
 * bounds the number of roots, with the same parity (Descartes' rule for the Bernstein basis).
 * Returns 0 when every coefficient has one sign beyond its rounding margin (no root), 1 when all
 * signs are certain and V = 1 (exactly one simple root; guesses[0] is where the control
 * polygon crosses zero: guesses[0]), −1 otherwise. About 3n²/2 flops.
 */
function bernstein(n: number, lo: number, hi: number): number {
  const T = bufA; // Taylor coefficients at lo, then scaled by h^k, then Bernstein coefficients
  const A = bufB; // the same for |p| at |lo| (the scale of the rounding errors)
  const p = P;
  for (let i = 0; i <= n; i++) {
    const c = p[i] as number;
    T[i] = c;
    A[i] = c < 0 ? -c : c;
  }
  if (lo !== 0) {
    const al = lo < 0 ? -lo : lo;
    for (let k = 0; k < n; k++) {
      for (let i = n - 1; i >= k; i--) {
        T[i] = (T[i] as number) + lo * (T[i + 1] as number);
        A[i] = (A[i] as number) + al * (A[i + 1] as number);
      }
    }
  }
  const h = (hi - lo) * (1 + 4 * UNIT_ROUNDOFF);
  let hk = 1;
  let scale = A[0] as number;
  const inv = n < INV_BINOM.length ? (INV_BINOM[n] as Float64Array) : invBinom(n);
  for (let k = 1; k <= n; k++) {
    hk *= h;
    T[k] = (T[k] as number) * hk * (inv[k] as number);
    scale += (A[k] as number) * hk;
  }
  for (let r = 1; r <= n; r++) {
    for (let j = n; j >= r; j--) T[j] = (T[j] as number) + (T[j - 1] as number);
  }
  const margin = 4 * (n + 2) * UNIT_ROUNDOFF * scale;
  derivChanges = -1;
  if (!(margin < Number.POSITIVE_INFINITY)) return -1;
  // p′ on the same interval has the Bernstein coefficients (n/h)(b[j+1] − b[j]): count their signs.
  const dMargin = 3 * margin;
  let dPrev = (T[1] as number) - (T[0] as number);
  if (dPrev > dMargin || dPrev < -dMargin) {
    let dChanges = 0;
    for (let j = 1; j < n && dChanges <= 1; j++) {
      const d = (T[j + 1] as number) - (T[j] as number);
      if (!(d > dMargin || d < -dMargin)) {
        dChanges = -1;
        break;
      }
      if (d < 0 !== dPrev < 0) {
        dChanges++;
        guesses[1] = lo + (h * (j - 1 + dPrev / (dPrev - d))) / (n - 1);
      }
      dPrev = d;
    }
    derivChanges = dChanges <= 1 ? dChanges : -1;
  }
  let prev = T[0] as number;
  if (!(prev > margin || prev < -margin)) return -1;
  let changes = 0;
  for (let j = 1; j <= n; j++) {
    const t = T[j] as number;
    if (!(t > margin || t < -margin)) return -1;
    if (t < 0 !== prev < 0) {
      if (++changes > 1) return -1;
      guesses[0] = lo + (h * (j - 1 + prev / (prev - t))) / n;
    }
    prev = t;
  }
  return changes;
}
/**
 * Double-valued results of bernstein(), kept in a typed array: storing a double into a module-level
 * `let` allocates a heap number on every store, which showed up in profiles. [0] = where p's control
 * polygon crosses zero (one sign change), [1] = the same for p′.
 */
const guesses = new Float64Array(2);
/** Certified sign changes of p′'s Bernstein coefficients on the same interval: 0, 1, or −1 (more/unknown). */
let derivChanges = -1;

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

/**
 * bernstein() for degree 4 in scalar arithmetic (no typed-array traffic: this is the hot path of
 * collision quartics, most of which stop here). Same results contract as bernstein(); its
 * Bernstein coefficients are computed directly as b_j = Σ_k C(j,k) a_k, a_k = T_k h^k / C(4,k).
 */
function bernstein4(
  c0: number,
  c1: number,
  c2: number,
  c3: number,
  c4: number,
  lo: number,
  hi: number,
): number {
  let t0 = c0;
  let t1 = c1;
  let t2 = c2;
  let t3 = c3;
  let s0 = c0 < 0 ? -c0 : c0;
  let s1 = c1 < 0 ? -c1 : c1;
  let s2 = c2 < 0 ? -c2 : c2;
  let s3 = c3 < 0 ? -c3 : c3;
  const s4 = c4 < 0 ? -c4 : c4;
  if (lo !== 0) {
    // Taylor shift to lo (synthetic division), and of |p| to |lo| for the error scale.
    const al = lo < 0 ? -lo : lo;
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
    s3 += al * s4;
    s2 += al * s3;
    s1 += al * s2;
    s0 += al * s1;
    s3 += al * s4;
    s2 += al * s3;
    s1 += al * s2;
    s3 += al * s4;
    s2 += al * s3;
    s3 += al * s4;
  }
  const h = (hi - lo) * (1 + 4 * UNIT_ROUNDOFF);
  const h2 = h * h;
  const h3 = h2 * h;
  const h4 = h2 * h2;
  const a1 = t1 * h * 0.25;
  const a2 = (t2 * h2) / 6;
  const a3 = t3 * h3 * 0.25;
  const a4 = c4 * h4;
  const margin = 24 * UNIT_ROUNDOFF * (s0 + s1 * h + s2 * h2 + s3 * h3 + s4 * h4);
  derivChanges = -1;
  if (!(margin < Number.POSITIVE_INFINITY)) return -1;
  // p′'s Bernstein coefficients (up to the factor 4/h): d_j = b_{j+1} − b_j.
  const d0 = a1;
  const d1 = a1 + a2;
  const d2 = a1 + 2 * a2 + a3;
  const d3 = a1 + 3 * a2 + 3 * a3 + a4;
  const dm = 3 * margin;
  if ((d0 > dm || d0 < -dm) && (d1 > dm || d1 < -dm) && (d2 > dm || d2 < -dm) && (d3 > dm || d3 < -dm)) {
    let k = 0;
    if (d1 < 0 !== d0 < 0) {
      k++;
      guesses[1] = lo + (h * (d0 / (d0 - d1))) / 3;
    }
    if (d2 < 0 !== d1 < 0) {
      k++;
      guesses[1] = lo + (h * (1 + d1 / (d1 - d2))) / 3;
    }
    if (d3 < 0 !== d2 < 0) {
      k++;
      guesses[1] = lo + (h * (2 + d2 / (d2 - d3))) / 3;
    }
    derivChanges = k <= 1 ? k : -1;
  }
  const b0 = t0;
  const b1 = t0 + a1;
  const b2 = t0 + 2 * a1 + a2;
  const b3 = t0 + 3 * a1 + 3 * a2 + a3;
  const b4 = t0 + 4 * a1 + 6 * a2 + 4 * a3 + a4;
  if ((b0 > margin && b4 > margin) || (b0 < -margin && b4 < -margin)) {
    // Same sign at both ends: no root, or an even number. One de Casteljau split at the middle
    // often proves none (the halves' coefficients are averages: error ≤ margin + 4u·max|b| ≤ 2·margin).
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
    const m2x = 2 * margin;
    if (b0 > 0) {
      if (l1 > m2x && l2 > m2x && l3 > m2x && mid > m2x && r1 > m2x && r2 > m2x && r3 > m2x) return 0;
    } else if (l1 < -m2x && l2 < -m2x && l3 < -m2x && mid < -m2x && r1 < -m2x && r2 < -m2x && r3 < -m2x) {
      return 0;
    }
  }
  if (!(b0 > margin || b0 < -margin) || !(b1 > margin || b1 < -margin)) return -1;
  if (!(b2 > margin || b2 < -margin) || !(b3 > margin || b3 < -margin) || !(b4 > margin || b4 < -margin)) {
    return -1;
  }
  let k = 0;
  if (b1 < 0 !== b0 < 0) {
    k++;
    guesses[0] = lo + (h * (b0 / (b0 - b1))) / 4;
  }
  if (b2 < 0 !== b1 < 0) {
    k++;
    guesses[0] = lo + (h * (1 + b1 / (b1 - b2))) / 4;
  }
  if (b3 < 0 !== b2 < 0) {
    k++;
    guesses[0] = lo + (h * (2 + b2 / (b2 - b3))) / 4;
  }
  if (b4 < 0 !== b3 < 0) {
    k++;
    guesses[0] = lo + (h * (3 + b3 / (b3 - b4))) / 4;
  }
  return k <= 1 ? k : -1;
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
  if (typeof lo !== "number" || Number.isNaN(lo))
    throw new RangeError(`realRoots: lo must be a number, got ${lo}`);
  if (typeof hi !== "number" || Number.isNaN(hi))
    throw new RangeError(`realRoots: hi must be a number, got ${hi}`);
  const len = coeffs.length;
  let n = -1;
  let maxAbs = 0;
  for (let i = 0; i < len; i++) {
    const c = coeffs[i] as number;
    if (typeof c !== "number" || !(c - c === 0)) {
      throw new RangeError(`realRoots: coeffs[${i}] must be a finite number, got ${c}`);
    }
    if (c !== 0) {
      n = i;
      const a = c < 0 ? -c : c;
      if (a > maxAbs) maxAbs = a;
    }
  }
  const out: number[] = [];
  if (!(lo <= hi) || n < 1) return out;
  ensure(n);
  // Cauchy's bound: every root has |t| < 1 + max_{i<n} |c_i / c_n| ≤ 1 + max_i |c_i| / |c_n|.
  const bound = (1 + maxAbs / Math.abs(coeffs[n] as number)) * (1 + 2 ** -48);
  const B = bound < Number.POSITIVE_INFINITY ? bound : Number.MAX_VALUE;
  if (lo < -B) lo = -B;
  if (hi > B) hi = B;
  if (lo > hi) return out;
  const M = Math.max(-lo, hi, lo, -hi);
  // Hot path (collision quartics): a quartic needing no scaling is first tested by the scalar
  // Bernstein check, before anything is copied; most stop here.
  let v = -2;
  if (
    n === 4 &&
    lo < hi &&
    maxAbs >= SMALL &&
    maxAbs <= BIG &&
    M <= (MOD_LIMIT[4] as number) &&
    M * (MOD_LIMIT[4] as number) >= 1
  ) {
    v = bernstein4(
      coeffs[0] as number,
      coeffs[1] as number,
      coeffs[2] as number,
      coeffs[3] as number,
      coeffs[4] as number,
      lo,
      hi,
    );
    if (v === 0) return out;
  }
  // Exact power-of-two scaling: coefficients to about 1 and, for extreme intervals, the variable
  // (t = 2^xs·s) so that |s| ≤ 1; the roots are unchanged (up to that exact factor).
  const xs = normalise(coeffs, n, maxAbs, M);
  if (xs !== 0) {
    lo = mulPow2(lo, -xs);
    hi = mulPow2(hi, -xs);
  }
  load(P, n, coeffs, xs);
  if (lo === hi) {
    if (certSign(lo) === 0) out.push(lo);
  } else {
    solveScaled(n, lo, hi, out, xs === 0 ? v : -2);
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
  return out;
}

/**
 * Fill P with the coefficients, scaled by exact powers of two when needed: returns xs, the exponent
 * of the variable scaling (0 when the interval is moderate: |log2 M|·n ≤ 256). Coefficients are then
 * scaled to a largest magnitude near 1, unless it is already within [2^-64, 2^64]. Coefficients more
 * than ~2^1070 below the largest underflow (documented limit).
 */
function normalise(coeffs: ArrayLike<number>, n: number, maxAbs: number, M: number): number {
  // Fast test first (|log2 M|·n ≤ 256 ⇐ 2^(-256/n) ≤ M ≤ 2^(256/n)); exponents only when it fails.
  const lim = n < MOD_LIMIT.length ? (MOD_LIMIT[n] as number) : 1;
  let xs = 0;
  if (!(M <= lim && (M >= 1 / lim || M === 0))) {
    const eM = M > 0 && M < Number.POSITIVE_INFINITY ? exponentOf(M) : 0;
    xs = n * Math.abs(eM) > 256 ? eM + 1 : 0;
  }
  if (xs === 0 && maxAbs >= SMALL && maxAbs <= BIG) {
    const p = P;
    for (let i = 0; i <= n; i++) p[i] = coeffs[i] as number;
    return 0;
  }
  let E = Number.NEGATIVE_INFINITY;
  for (let i = 0; i <= n; i++) {
    const c = coeffs[i] as number;
    if (c !== 0) E = Math.max(E, exponentOf(c) + xs * i);
  }
  for (let i = 0; i <= n; i++) P[i] = mulPow2(coeffs[i] as number, xs * i - E);
  return xs;
}

/**
 * The solve proper on the normalised polynomial P (degree n) over lo < hi; appends to out. `known`
 * is bernstein()'s result when the caller already computed it (−2 otherwise).
 */
function solveScaled(n: number, lo: number, hi: number, out: number[], known: number): void {
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
  const v = known !== -2 ? known : bernstein(n, lo, hi); // −2: not computed yet
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
  solveLevel0(n, m, lo, hi, ns, out);
}

/** Certified signs at lo, the critical points and hi; one refined root per sign change. */
function solveLevel0(n: number, m: number, lo: number, hi: number, ns: number, out: number[]): void {
  let K = ns + 2;
  pts[0] = lo;
  for (let i = 0; i < ns; i++) pts[i + 1] = bufA[i] as number;
  pts[K - 1] = hi;
  let anyNoisy = false;
  for (let i = 0; i < K; i++) {
    sgn[i] = certSign(pts[i] as number);
    absv[i] = lastAbsValue();
    noisy[i] = lastWasNoisy() ? 1 : 0;
    if (noisy[i] === 1 && i > 0 && i < K - 1) anyNoisy = true;
  }
  if (anyNoisy) K = exactCriticalNeighbours(K, n);
  // Grazing (double-root) candidates: noisy critical points with no sign change on either side.
  for (let i = 1; i < K - 1; i++) {
    const s = sgn[i] as number;
    if (noisy[i] === 0 || s === 0 || sgn[i - 1] === -s || sgn[i + 1] === -s) continue;
    if (!criticalPoint(pts[i] as number, pts[i - 1] as number, pts[i + 1] as number, crit)) continue;
    let best = -1;
    let bestAbs = Number.POSITIVE_INFINITY;
    for (let j = 0; j < 2; j++) {
      const x = crit[j] as number;
      const sx = certSign(x);
      if (sx !== s) {
        pts[i] = x; // the exact p reaches zero or crosses it here: ordinary pieces take over
        sgn[i] = sx;
        absv[i] = lastAbsValue();
        noisy[i] = 0;
        best = -2;
        break;
      }
      if (lastAbsValue() < bestAbs) {
        bestAbs = lastAbsValue();
        best = j;
      }
    }
    if (best >= 0) {
      pts[i] = crit[best] as number;
      sgn[i] = 0; // reported as a (double) root; its pieces have no sign change
      absv[i] = bestAbs;
    }
  }
  const quad = n === 2 && m === 2;
  let nq = 0;
  if (quad) nq = quadRootsPlain(P[0] as number, P[1] as number, P[2] as number, lo, hi, closed, 0);
  for (let i = 0; i < K; i++) {
    const a = pts[i] as number;
    const sa = sgn[i] as number;
    if (sa === 0) push(out, a);
    if (i === K - 1) break;
    const sb = sgn[i + 1] as number;
    if (sa === 0 || sb !== -sa) continue;
    const b = pts[i + 1] as number;
    const aa = absv[i] as number;
    const ab = absv[i + 1] as number;
    let x0 = Number.NaN;
    if (quad) {
      for (let j = 0; j < nq; j++)
        if ((closed[j] as number) > a && (closed[j] as number) < b) x0 = closed[j] as number;
    }
    if (Number.isNaN(x0)) {
      const crit = (i > 0 ? 1 : 0) | (i + 1 < K - 1 ? 2 : 0);
      x0 = newtonPlain(P, 0, n, a, b, sa * (aa > 0 ? aa : 1), -sa * (ab > 0 ? ab : 1), crit);
    }
    push(out, refineRoot(a, b, sa, aa, ab, x0));
  }
}

/**
 * Where p is at rounding-noise level at a critical point, plain arithmetic cannot resolve the
 * structure around it (a cluster of roots of p′): the nearest exact sign changes of p′ on each side
 * (found with certified signs, see certify.ts) are inserted as further piece ends with their exact
 * signs of p, and the search goes on beyond each inserted point while p is still at noise level
 * there, so that no root hides in a non-monotone piece. Returns the new number of points.
 */
function exactCriticalNeighbours(K: number, n: number): number {
  let k = K;
  const cap = 2 * n + 1; // lo, hi, and at most n − 1 structural plus n − 1 exact critical points
  // From the end, so that insertions do not disturb the indices still to visit.
  for (let i = K - 2; i >= 1; i--) {
    if (noisy[i] !== 1) continue;
    // Downwards: insert below, keep going while the inserted point is at noise level.
    let j = i;
    while (k < cap && nearestCritical(pts[j] as number, pts[j - 1] as number, crit)) {
      const y = pick(crit[1] as number, crit[0] as number);
      if (!(y < (pts[j] as number) && y > (pts[j - 1] as number))) break;
      k = insertPoint(k, j, y);
      if (noisy[j] !== 1) break;
    }
    // Upwards from the original point, which moved up by the insertions below it.
    j = i + (k - K);
    while (k < cap && nearestCritical(pts[j] as number, pts[j + 1] as number, crit)) {
      const y = pick(crit[0] as number, crit[1] as number);
      if (!(y > (pts[j] as number) && y < (pts[j + 1] as number))) break;
      k = insertPoint(k, j + 1, y);
      j++;
      if (noisy[j] !== 1) break;
    }
    K = k;
  }
  return k;
}

/** Of the two doubles around a sign change of p′, one where p is exactly 0 if any, else `first`. */
function pick(first: number, second: number): number {
  if (first === second || certSign(first) === 0) return first;
  return certSign(second) === 0 ? second : first;
}

/** Insert x (with its exact sign of p) at index j of the point list of length k; returns k + 1. */
function insertPoint(k: number, j: number, x: number): number {
  for (let t = k; t > j; t--) {
    pts[t] = pts[t - 1] as number;
    sgn[t] = sgn[t - 1] as number;
    absv[t] = absv[t - 1] as number;
    noisy[t] = noisy[t - 1] as number;
  }
  pts[j] = x;
  sgn[j] = certSign(x);
  absv[j] = lastAbsValue();
  noisy[j] = lastWasNoisy() ? 1 : 0;
  return k + 1;
}

function push(out: number[], x: number): void {
  if (out.length === 0 || x > (out[out.length - 1] as number)) out.push(x + 0); // −0 → +0
}
