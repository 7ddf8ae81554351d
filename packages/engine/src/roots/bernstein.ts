/**
 * Quick sign checks on the Bernstein coefficients of a polynomial over an interval (pure except for
 * the exported result slots below).
 *
 * - `bernstein(p, n, lo, hi, T, A)`: from a Taylor shift to lo and scaling to [lo, lo + h]
 *   (h ≥ hi − lo); every coefficient's sign certified against a rounding margin. Returns 0 (one sign:
 *   no root), 1 (exactly one sign change: one simple root; `guesses[0]` = where the control polygon
 *   crosses zero) or −1; also sets `derivChanges` (the same count for p′, from the differences of the
 *   coefficients: 0, 1 or −1) and `guesses[1]`.
 * (The quartic hot path, quartic.ts, computes the same coefficients in scalar arithmetic and
 * subdivides them.)
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
 * Double-valued results of bernstein(), kept in a typed array: storing a double into a module-level
 * `let` allocates a heap number on every store, which showed up in profiles. [0] = where p's control
 * polygon crosses zero (one sign change), [1] = the same for p′.
 */
export const guesses: Float64Array = new Float64Array(2);
/** Certified sign changes of p′'s Bernstein coefficients on the same interval: 0, 1, or −1 (more/unknown). */
export let derivChanges = -1;
