/**
 * Quick sign checks on the Bernstein coefficients of a polynomial over an interval (pure except for
 * the exported result slots below).
 *
 * - `bernstein(p, n, lo, hi, T, A)`: from a Taylor shift to lo and scaling to [lo, lo + h]
 *   (h ≥ hi − lo); every coefficient's sign certified against a rounding margin. Returns 0 (one sign:
 *   no root), 1 (exactly one sign change: one simple root; `guesses[0]` = where the control polygon
 *   crosses zero) or −1; also sets `derivChanges` (the same count for p′, from the differences of the
 *   coefficients: 0, 1 or −1) and `guesses[1]`.
 * - `bernstein4(c0, …, c4, lo, hi)`: the same for degree 4 in scalar arithmetic (the collision hot
 *   path), plus one de Casteljau split at the middle when both ends have one sign.
 * Convex hull property: p lies within the range of its Bernstein coefficients; Descartes' rule for
 * the Bernstein basis: roots in the interval ≤ sign changes, with the same parity.
 */

import { UNIT_ROUNDOFF } from "../tolerances.js";

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
/**
 * Quick sign checks with the Bernstein coefficients of p on [lo, lo + h] (h ≥ hi − lo, from a
 * Taylor shift): they bound p there (convex hull property), and their number of sign changes V
 * bounds the number of roots, with the same parity (Descartes' rule for the Bernstein basis).
 * Returns 0 when every coefficient has one sign beyond its rounding margin (no root), 1 when all
 * signs are certain and V = 1 (exactly one simple root; guesses[0] is where the control
 * polygon crosses zero: guesses[0]), −1 otherwise. About 3n²/2 flops.
 */
export function bernstein(
  p: Float64Array,
  n: number,
  lo: number,
  hi: number,
  T: Float64Array,
  A: Float64Array,
): number {
  // T: Taylor coefficients at lo, then scaled by h^k, then Bernstein coefficients; A: the same for
  // |p| at |lo| (the scale of the rounding errors). Both are caller scratch of length ≥ n + 1.
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
 * Double-valued results of bernstein() and bernstein4(), kept in a typed array: storing a double into a module-level
 * `let` allocates a heap number on every store, which showed up in profiles. [0] = where p's control
 * polygon crosses zero (one sign change), [1] = the same for p′.
 */
export const guesses = new Float64Array(2);
/** Certified sign changes of p′'s Bernstein coefficients on the same interval: 0, 1, or −1 (more/unknown). */
export let derivChanges = -1;

/**
 * bernstein() for degree 4 in scalar arithmetic (no typed-array traffic: this is the hot path of
 * collision quartics, most of which stop here). Same results contract as bernstein(); its
 * Bernstein coefficients are computed directly as b_j = Σ_k C(j,k) a_k, a_k = T_k h^k / C(4,k).
 */
export function bernstein4(
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
