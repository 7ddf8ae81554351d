/**
 * When a centre moving along one axis leaves a cell's interval (pure function).
 *
 * p(tau) = p0 + v tau + ha tau^2 (ha = half the acceleration); the cell spans [lower, upper], either
 * end may be infinite (edge cells extend to infinity). Returns the first tau in [lo, hi] at which the
 * centre crosses a finite end outwards, or +Infinity, and writes the side (-1 lower, +1 upper) to
 * side[0]. A centre already outside by a rounding error while moving outwards exits at lo.
 */
import { firstDownCrossingQuadratic } from "../physics/quadraticCrossing.js";

export function axisExit(
  p0: number,
  v: number,
  ha: number,
  lo: number,
  hi: number,
  lower: number,
  upper: number,
  side: Float64Array,
): number {
  side[0] = 0;
  if (ha === 0) {
    // Uniform motion (the common case): only the end ahead can be crossed, at a division.
    if (v > 0 && upper !== Number.POSITIVE_INFINITY) {
      side[0] = 1;
      return Math.max(lo, (upper - p0) / v);
    }
    if (v < 0 && lower !== Number.NEGATIVE_INFINITY) {
      side[0] = -1;
      return Math.max(lo, (lower - p0) / v);
    }
    return Number.POSITIVE_INFINITY;
  }
  let best = Number.POSITIVE_INFINITY;
  if (lower !== Number.NEGATIVE_INFINITY) {
    best = firstDownCrossingQuadratic(p0 - lower, v, ha, lo, hi);
    if (best !== Number.POSITIVE_INFINITY) side[0] = -1;
  }
  if (upper !== Number.POSITIVE_INFINITY) {
    const t = firstDownCrossingQuadratic(upper - p0, -v, -ha, lo, hi);
    if (t < best) {
      best = t;
      side[0] = 1;
    }
  }
  return best;
}
