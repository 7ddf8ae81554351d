/**
 * Plain-arithmetic kernels of the solver: safeguarded Newton on a bracket, the cancellation-free
 * quadratic formula, and the roots of a polynomial on monotone pieces.
 *
 * - `newtonPlain(c, off, n, a, b, fa, fb, critical)`: a root of the degree-n polynomial
 *   c[off..off+n] in (a, b), given plain values fa, fb of opposite signs (`critical` marks ends
 *   that are critical points, for a better start; `guess`, when inside, is the start). Halley steps (Newton with the second
 *   derivative: cubic convergence, so fewer evaluations) are accepted only inside the current
 *   bracket and while they at least halve the step before last; otherwise the bracket is
 *   split (splitPoint); after NEWTON_STEPS steps only splitting. Stops when a Halley step follows a Newton step below 2^-17 relative (the error
 *   left is then about an ulp at a simple root) or the bracket is two adjacent
 *   doubles. Signs here are plain Horner signs: the result is as good as plain evaluation allows;
 *   callers that need certainty refine it (see certify.ts).
 * - `quadRootsPlain(c0, c1, c2, lo, hi, out, k)`: roots of c2 t² + c1 t + c0 strictly inside (lo, hi)
 *   with q = −(c1 + sign(c1)√disc)/2, roots q/c2 and c0/q (no cancellation), appended to out[k…];
 *   returns the new count. A discriminant within its rounding error of 0 gives the vertex (a
 *   possible double root): these roots are split points, where an extra one is harmless.
 * - `pieceRoots(c, off, n, lo, hi, splits, ns, out)`: the roots strictly inside (lo, hi) of a
 *   polynomial monotone between consecutive splits (its critical points), sorted, into out; returns
 *   the count. Critical points where the value is at rounding-noise level without a sign change are
 *   included (possible double roots).
 */

import { PLAIN_HORNER_BOUND_FACTOR, ROOTS_MAX_ITERATIONS, UNIT_ROUNDOFF } from "../tolerances.js";
import { RootSolverError, splitPoint } from "./bracket.js";

/**
 * Stop once Newton's step is below 2^-17 of |x| and Halley's step is taken: with cubic convergence
 * the error left is about (2^-17)³ = 2^-51 relative (an ulp or two) at a simple root; at multiple or
 * clustered roots the result is less precise, which is harmless here (split points only need to be
 * close, and level-0 roots are certified afterwards by certify.ts).
 */
const EARLY = 2 ** -17;
/**
 * Newton steps allowed before pure halving: Newton converges in a handful of steps at simple roots
 * but only linearly (halving) at multiple roots, which near 0 could take ~1000 steps; halving in the
 * ordering of doubles then ends in at most about 120 more.
 */
const NEWTON_STEPS = 20;

/** Safeguarded Halley/Newton on a bracket with plain values of opposite signs at its ends. */
export function newtonPlain(
  c: ArrayLike<number>,
  off: number,
  n: number,
  a: number,
  b: number,
  fa: number,
  fb: number,
  critical = 0,
  guess = Number.NaN,
  maxIterations = ROOTS_MAX_ITERATIONS,
): number {
  const aNeg = fa < 0;
  let x = guess > a && guess < b ? guess : start(c, off, n, a, b, fa, fb, critical);
  if (!(x > a && x < b)) x = splitPoint(a, b);
  let dxOld = Number.POSITIVE_INFINITY;
  let dx = Number.POSITIVE_INFINITY;
  for (let it = 0; it < maxIterations; it++) {
    // p, p' and p''/2 at x in one Horner pass.
    let f = c[off + n] as number;
    let d1 = 0;
    let d2 = 0;
    for (let i = n - 1; i >= 0; i--) {
      d2 = d2 * x + d1;
      d1 = d1 * x + f;
      f = f * x + (c[off + i] as number);
    }
    if (f === 0) return x;
    if (f < 0 === aNeg) a = x;
    else b = x;
    // Halley's step (cubic convergence) where it is a small correction of Newton's step
    // (|f p''/2| ≤ d1²/2); Newton's elsewhere. Near a critical point (d1 → 0) Halley's step tends
    // to 0 although no root is near, so convergence is judged on Newton's step |f/d1| only.
    const fd2 = f * d2;
    const d11 = d1 * d1;
    const halley = (fd2 < 0 ? -fd2 : fd2) <= 0.5 * d11;
    const step = halley && it < NEWTON_STEPS ? (f * d1) / (d11 - fd2) : f / d1;
    const as = step < 0 ? -step : step;
    const ax = x < 0 ? -x : x;
    let xn = x - step;
    if (halley && (f < 0 ? -f : f) <= EARLY * ax * (d1 < 0 ? -d1 : d1) && xn >= a && xn <= b) return xn;
    if (it >= NEWTON_STEPS || !(xn > a && xn < b) || as > 0.5 * (dxOld < 0 ? -dxOld : dxOld)) {
      xn = splitPoint(a, b);
      if (xn === a) return x; // a and b adjacent
    }
    dxOld = dx;
    dx = xn - x;
    x = xn;
  }
  throw new RootSolverError(`newton: no convergence in ${maxIterations} iterations on [${a}, ${b}]`);
}

/**
 * Starting point in (a, b). At an end that is a critical point (bit 1: a, bit 2: b; p' = 0 there)
 * p(e + δ) ≈ p(e) + p''(e) δ²/2, so δ = √(−2p(e)/p''(e)): much closer than the secant, which is
 * poor next to a flat end. With two critical ends the one with the smaller |p| is used. Otherwise
 * (or when the model fails) regula falsi.
 */
function start(
  c: ArrayLike<number>,
  off: number,
  n: number,
  a: number,
  b: number,
  fa: number,
  fb: number,
  critical: number,
): number {
  if (critical !== 0) {
    const useA = critical === 1 || (critical === 3 && Math.abs(fa) <= Math.abs(fb));
    const e = useA ? a : b;
    const fe = useA ? fa : fb;
    let d1 = 0;
    let d2 = 0;
    let f = c[off + n] as number;
    for (let i = n - 1; i >= 0; i--) {
      d2 = d2 * e + d1;
      d1 = d1 * e + f;
      f = f * e + (c[off + i] as number);
    }
    const q = -fe / d2; // δ² (d2 = p''/2)
    if (q > 0) {
      const x = useA ? a + Math.sqrt(q) : b - Math.sqrt(q);
      if (x > a && x < b) return x;
    }
  }
  return a - fa * ((b - a) / (fb - fa));
}

/** Roots of c2 t² + c1 t + c0 (c2 ≠ 0) strictly inside (lo, hi), sorted, appended at out[k]. */
export function quadRootsPlain(
  c0: number,
  c1: number,
  c2: number,
  lo: number,
  hi: number,
  out: Float64Array,
  k: number,
): number {
  // Discriminant with error-free products (Dekker): b² and 4ac exactly as double-doubles, so
  // nearly double roots (critical points a hair apart) are still told apart.
  const b2 = c1 * c1;
  const b2e = twoProductError(c1, c1, b2);
  const ac = c2 * c0;
  const ace = twoProductError(c2, c0, ac);
  const ac4 = 4 * ac;
  const disc = b2 - ac4 + (b2e - 4 * ace);
  const noiseD =
    8 * UNIT_ROUNDOFF * UNIT_ROUNDOFF * (b2 + (ac4 < 0 ? -ac4 : ac4)) +
    4 * UNIT_ROUNDOFF * (disc < 0 ? -disc : disc);
  let r1: number;
  let r2: number;
  if (c0 === 0) {
    // Exact root 0 (also when c1² underflows, which would merge the two roots).
    r1 = 0;
    r2 = -c1 / c2;
    if (r1 > r2) {
      r1 = r2;
      r2 = 0;
    }
  } else if (disc <= noiseD) {
    // No real roots, or a double root within the discriminant's rounding: report the vertex (a
    // possible double root; for splitting, an extra point is harmless, a missing one is not).
    if (!(disc >= -noiseD)) return k;
    r1 = r2 = -c1 / (2 * c2);
  } else {
    const sq = Math.sqrt(disc);
    const q = c1 >= 0 ? -0.5 * (c1 + sq) : -0.5 * (c1 - sq);
    r1 = q / c2;
    r2 = c0 / q;
    if (r1 > r2) {
      const t = r1;
      r1 = r2;
      r2 = t;
    }
  }
  if (r1 > lo && r1 < hi) out[k++] = r1;
  if (r2 !== r1 && r2 > lo && r2 < hi) out[k++] = r2;
  return k;
}

/** The rounding error of the product p = fl(a·b): a·b − p exactly (Dekker's TwoProduct). */
function twoProductError(a: number, b: number, p: number): number {
  let t = 134217729 * a;
  const ah = t - (t - a);
  const al = a - ah;
  t = 134217729 * b;
  const bh = t - (t - b);
  const bl = b - bh;
  return al * bl - (p - ah * bh - al * bh - ah * bl);
}

let vals = new Float64Array(8);
let noise = new Uint8Array(8);
const hb = new Float64Array(2);

/**
 * Roots strictly inside (lo, hi) of a polynomial monotone between consecutive sorted splits. A split
 * (critical point) where the value is 0, or within the plain error bound with no sign change on
 * either side, is reported as a (possibly double) root: for the next level it is a split point,
 * and an extra split point is harmless while a missing one could hide a multiple root.
 */
export function pieceRoots(
  c: ArrayLike<number>,
  off: number,
  n: number,
  lo: number,
  hi: number,
  splits: Float64Array,
  ns: number,
  out: Float64Array,
): number {
  if (vals.length < ns + 2) {
    vals = new Float64Array(ns + 2);
    noise = new Uint8Array(ns + 2);
  }
  const K = ns + 2;
  for (let i = 0; i < K; i++) {
    const x = i === 0 ? lo : i === K - 1 ? hi : (splits[i - 1] as number);
    boundAt(c, off, n, x, hb);
    const v = hb[0] as number;
    vals[i] = v;
    noise[i] = (v < 0 ? -v : v) <= (hb[1] as number) ? 1 : 0;
  }
  let k = 0;
  for (let i = 0; i < K; i++) {
    const fa = vals[i] as number;
    if (i > 0 && i < K - 1) {
      const b = splits[i - 1] as number;
      const fp = vals[i - 1] as number;
      const fn = vals[i + 1] as number;
      const graze = noise[i] === 1 && !(fp < 0 !== fa < 0 && fp !== 0) && !(fn < 0 !== fa < 0 && fn !== 0);
      if ((fa === 0 || graze) && (k === 0 || b > (out[k - 1] as number))) out[k++] = b;
    }
    if (i === K - 1) break;
    const fb = vals[i + 1] as number;
    if (fa !== 0 && fb !== 0 && fa < 0 !== fb < 0) {
      const a = i === 0 ? lo : (splits[i - 1] as number);
      const b = i + 1 === K - 1 ? hi : (splits[i] as number);
      const r = newtonPlain(c, off, n, a, b, fa, fb, (i > 0 ? 1 : 0) | (i < ns ? 2 : 0));
      if (r > lo && r < hi && (k === 0 || r > (out[k - 1] as number))) out[k++] = r;
    }
  }
  return k;
}

/** Plain Horner value and its error bound (hornerBound on an offset coefficient array). */
function boundAt(c: ArrayLike<number>, off: number, n: number, x: number, o: Float64Array): void {
  const ax = x < 0 ? -x : x;
  let s = c[off + n] as number;
  let a = s < 0 ? -s : s;
  for (let i = n - 1; i >= 0; i--) {
    const ci = c[off + i] as number;
    s = s * x + ci;
    a = a * ax + (ci < 0 ? -ci : ci);
  }
  o[0] = s;
  o[1] = PLAIN_HORNER_BOUND_FACTOR * n * UNIT_ROUNDOFF * a;
}
