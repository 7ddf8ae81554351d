/**
 * Bracketing helpers for the root solver.
 *
 * - `splitPoint(a, b)`: a double strictly between a < b (when one exists) that halves the bracket in
 *   the ordering of doubles once a and b differ by more than a factor of 2 (or have opposite signs),
 *   and halves it by value otherwise. So any bracket reaches adjacent doubles in at most about
 *   64 + 53 halvings, whatever the magnitudes (plain value halving could need over 2000).
 * - `RootSolverError`: thrown when a refinement loop exceeds its iteration cap (ROOTS_MAX_ITERATIONS).
 *   It should be unreachable (every loop provably shrinks its bracket); it exists so that a bug shows
 *   as a clear error instead of an endless loop or a silent guess.
 */

const f64 = new Float64Array(1);
const u32 = new Uint32Array(f64.buffer);
const HI = (() => {
  f64[0] = 1;
  return u32[1] === 0x3ff00000 ? 1 : 0;
})();
const LO = 1 - HI;
const TWO32 = 4294967296;

/** Position of x ≥ 0 in the ordering of doubles, as a (rounded) number. */
function ordinal(x: number): number {
  f64[0] = x + 0; // −0 → +0
  return (u32[HI] as number) * TWO32 + (u32[LO] as number);
}

/** The double x ≥ 0 at (about) ordinal position o. */
function fromOrdinal(o: number): number {
  const hi = Math.floor(o / TWO32);
  let lo = Math.floor(o - hi * TWO32);
  if (lo < 0) lo = 0;
  if (lo >= TWO32) lo = TWO32 - 1;
  u32[HI] = hi;
  u32[LO] = lo;
  return f64[0] as number;
}

/** A double strictly inside (a, b) for a < b, or a when a and b are adjacent. */
export function splitPoint(a: number, b: number): number {
  a += 0; // −0 → +0 (its bit pattern would read as a huge ordinal)
  b += 0;
  let m: number;
  if (a < 0 && b > 0) {
    m = 0;
  } else if ((a >= 0 && b <= 2 * a) || (b <= 0 && a >= 2 * b)) {
    m = a + (b - a) * 0.5;
  } else if (a >= 0) {
    m = fromOrdinal(0.5 * (ordinal(a) + ordinal(b)));
  } else {
    m = -fromOrdinal(0.5 * (ordinal(-a) + ordinal(-b)));
  }
  if (m > a && m < b) return m;
  const m2 = a * 0.5 + b * 0.5;
  return m2 > a && m2 < b ? m2 : a;
}

/** Thrown when a root refinement loop exceeds its iteration cap (should never happen). */
export class RootSolverError extends Error {
  constructor(message: string) {
    super(message);
    this.name = "RootSolverError";
  }
}
