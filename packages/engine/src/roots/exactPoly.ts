/**
 * Exact arithmetic on polynomials with double coefficients, for verification and for the solver's
 * rare fallback when a compensated evaluation cannot decide a sign.
 *
 * Contract:
 * - `exactPolySign(coeffs, x)`: the exact sign of c0 + c1 x + … + cn xⁿ, with the doubles taken at
 *   their exact values (every finite double is m·2^e with integer m, e). Computed with BigInt dyadic
 *   numbers, so no rounding at all. Throws a RangeError naming the function and the field for a
 *   non-finite input or coefficients that are not an array-like (`exactPolySign(x): must be a
 *   finite number (got the string "1")`, the value shown as every refusal of the engine shows it).
 * - `exactDerivativeSign(coeffs, x)`: the same for the first derivative c1 + 2 c2 x + … (exact).
 * - `exactAbsCompare(coeffs, x1, x2)`: the sign of |p(x1)| − |p(x2)| (exact).
 * - `nextUp(x)` / `nextDown(x)`: the adjacent double above / below (IEEE-754 nextUp/nextDown).
 * - `ulpsToExactRoot(coeffs, x, maxUlps = 64)`: the smallest k ≥ 0 such that the exact polynomial is
 *   zero at, or changes sign between x and, the double k steps above or below x (so an exact root lies
 *   within k ulps of x); Infinity when there is none within maxUlps steps.
 * Pure functions; the typed-array views are module scratch (no allocation besides BigInts).
 */

import { given } from "../sim/refusalText.js";

const f64 = new Float64Array(1);
const u32 = new Uint32Array(f64.buffer);
/** Index of the high (sign/exponent) word in the Uint32 view: 1 on little-endian platforms. */
const HI = (() => {
  f64[0] = 1;
  return u32[1] === 0x3ff00000 ? 1 : 0;
})();
const LO = 1 - HI;

/** The adjacent double above x (nextUp(-0) = nextUp(0) = the smallest subnormal). */
export function nextUp(x: number): number {
  if (Number.isNaN(x) || x === Number.POSITIVE_INFINITY) return x;
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

/** The adjacent double below x. */
export function nextDown(x: number): number {
  return -nextUp(-x);
}

/** A finite double as an exact dyadic: mantissa·2^exponent (mantissa a signed BigInt). */
interface Dyadic {
  m: bigint;
  e: number;
}

function toDyadic(x: number, field: string): Dyadic {
  if (!Number.isFinite(x)) throw new RangeError(`${field}: must be a finite number (got ${given(x)})`);
  if (x === 0) return { m: 0n, e: 0 };
  f64[0] = x;
  const hi = u32[HI] as number;
  const lo = u32[LO] as number;
  const biased = (hi >>> 20) & 0x7ff;
  let mant = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  let e: number;
  if (biased === 0) e = -1074;
  else {
    mant |= 1n << 52n;
    e = biased - 1075;
  }
  return { m: x < 0 ? -mant : mant, e };
}

/** a + b exactly (aligning to the smaller exponent). */
function add(a: Dyadic, b: Dyadic): Dyadic {
  if (a.m === 0n) return b;
  if (b.m === 0n) return a;
  if (a.e === b.e) return { m: a.m + b.m, e: a.e };
  if (a.e > b.e) return { m: (a.m << BigInt(a.e - b.e)) + b.m, e: b.e };
  return { m: a.m + (b.m << BigInt(b.e - a.e)), e: a.e };
}

function signOf(m: bigint): -1 | 0 | 1 {
  return m > 0n ? 1 : m < 0n ? -1 : 0;
}

/** Exact value of Σ k_i c_i x^(i-shift) for i ≥ shift, where k_i = i (derivative) or 1; `fn`, the
 *  public function called, names the refused argument (`exactPolySign(x)`). */
function hornerValue(coeffs: ArrayLike<number>, x: number, derivative: boolean, fn: string): Dyadic {
  const len = coeffs === null || coeffs === undefined ? undefined : coeffs.length;
  if (typeof len !== "number" || !(len >= 0 && Math.floor(len) === len))
    throw new RangeError(`${fn}(coeffs): must be an array-like of finite numbers (got ${given(coeffs)})`);
  const xd = toDyadic(x, `${fn}(x)`);
  const start = derivative ? 1 : 0;
  let s: Dyadic = { m: 0n, e: 0 };
  for (let i = len - 1; i >= start; i--) {
    const c = toDyadic(coeffs[i] as number, `${fn}(coeffs[${i}])`);
    if (derivative) c.m *= BigInt(i);
    s = s.m === 0n ? c : add({ m: s.m * xd.m, e: s.e + xd.e }, c);
  }
  return s;
}

function hornerSign(coeffs: ArrayLike<number>, x: number, derivative: boolean, fn: string): -1 | 0 | 1 {
  return signOf(hornerValue(coeffs, x, derivative, fn).m);
}

/**
 * Exact comparison of |p(x1)| and |p(x2)|: -1 when |p(x1)| is smaller, 1 when larger, 0 when
 * equal (the root solver's tie-break between the two doubles around a root).
 */
export function exactAbsCompare(coeffs: ArrayLike<number>, x1: number, x2: number): -1 | 0 | 1 {
  const v1 = hornerValue(coeffs, x1, false, "exactAbsCompare");
  const v2 = hornerValue(coeffs, x2, false, "exactAbsCompare");
  const m1 = v1.m < 0n ? -v1.m : v1.m;
  const m2 = v2.m < 0n ? -v2.m : v2.m;
  const e = Math.min(v1.e, v2.e);
  return signOf((m1 << BigInt(v1.e - e)) - (m2 << BigInt(v2.e - e)));
}

/** Exact sign of the polynomial with double coefficients `coeffs` (ascending) at the double x. */
export function exactPolySign(coeffs: ArrayLike<number>, x: number): -1 | 0 | 1 {
  return hornerSign(coeffs, x, false, "exactPolySign");
}

/** Exact sign of the first derivative of the polynomial at the double x. */
export function exactDerivativeSign(coeffs: ArrayLike<number>, x: number): -1 | 0 | 1 {
  return hornerSign(coeffs, x, true, "exactDerivativeSign");
}

/**
 * How many ulps x is from an exact root of the polynomial: the smallest k such that the exact sign
 * is 0 at, or differs from the sign at x at, the double k steps above or below x. Infinity when
 * no such k ≤ maxUlps exists (walking stops at ±Infinity).
 */
export function ulpsToExactRoot(coeffs: ArrayLike<number>, x: number, maxUlps = 64): number {
  const s0 = hornerSign(coeffs, x, false, "ulpsToExactRoot");
  if (s0 === 0) return 0;
  let up = x;
  let down = x;
  for (let k = 1; k <= maxUlps; k++) {
    up = nextUp(up);
    down = nextDown(down);
    if (Number.isFinite(up) && exactPolySign(coeffs, up) !== s0) return k;
    if (Number.isFinite(down) && exactPolySign(coeffs, down) !== s0) return k;
  }
  return Number.POSITIVE_INFINITY;
}
