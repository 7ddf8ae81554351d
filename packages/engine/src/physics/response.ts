/**
 * Elastic collision response (pure functions). Velocities change along the line of centres (or the
 * obstacle's normal); tangential components are kept. Infinite masses are handled as the limits of
 * the finite formulas: an infinite mass keeps its velocity; two infinite masses exchange normal
 * velocity like equal masses. Results are written to a caller-owned output array.
 */

/** Half the largest double: above it, 2 * m overflows. */
const HALF_MAX = Number.MAX_VALUE / 2;
/** The smallest normal double: below it, products lose bits (and tiny masses' products vanish). */
const MIN_NORMAL = 2 ** -1022;

/**
 * Share of the normal velocity change taken by the body of mass `m` against mass `other`:
 * 2*other/(m + other), with the infinite limits. Masses near the top of the double range are
 * rescaled (halved, which is exact) so that 2*other or m + other cannot overflow to a NaN share.
 */
export function impulseShare(m: number, other: number): number {
  const mInf = m === Number.POSITIVE_INFINITY;
  const oInf = other === Number.POSITIVE_INFINITY;
  if (mInf) return oInf ? 1 : 0;
  if (oInf) return 2;
  if (other <= HALF_MAX && m <= HALF_MAX) return (2 * other) / (m + other);
  return other / (0.5 * m + 0.5 * other);
}

/**
 * Magnitude of the impulse 2*m1*m2/(m1+m2) * approachSpeed, with the infinite limits. Where the
 * product m1*m2 would overflow or underflow (masses beyond about 1e154 or below 1e-154 each) it is
 * computed as m2 * (2*m1/(m1+m2)), so a representable impulse is not reported as Infinity or 0.
 */
export function impulseMagnitude(m1: number, m2: number, approachSpeed: number): number {
  const inf1 = m1 === Number.POSITIVE_INFINITY;
  const inf2 = m2 === Number.POSITIVE_INFINITY;
  if (inf1 && inf2) return approachSpeed > 0 ? Number.POSITIVE_INFINITY : 0;
  if (inf1) return 2 * m2 * approachSpeed;
  if (inf2) return 2 * m1 * approachSpeed;
  const product = m1 * m2;
  if (product <= HALF_MAX && product >= MIN_NORMAL && m1 + m2 <= Number.MAX_VALUE)
    return ((2 * product) / (m1 + m2)) * approachSpeed;
  return m2 * impulseShare(m2, m1) * approachSpeed;
}

/**
 * Disc–disc: body 1 at p1 with v1 and mass m1, body 2 at p2 with v2 and mass m2, in contact.
 * Writes [v1x, v1y, v2x, v2y] after the collision into `out` and returns the approach speed along the
 * line of centres (> 0 when they approached; when <= 0 the velocities are copied unchanged).
 */
export function discDiscResponse(
  x1: number,
  y1: number,
  v1x: number,
  v1y: number,
  m1: number,
  x2: number,
  y2: number,
  v2x: number,
  v2y: number,
  m2: number,
  out: Float64Array,
): number {
  const dx = x1 - x2;
  const dy = y1 - y2;
  const dd = dx * dx + dy * dy;
  const k = ((v1x - v2x) * dx + (v1y - v2y) * dy) / dd;
  if (!(k < 0)) {
    out[0] = v1x;
    out[1] = v1y;
    out[2] = v2x;
    out[3] = v2y;
    return 0;
  }
  const s1 = impulseShare(m1, m2) * k;
  const s2 = impulseShare(m2, m1) * k;
  out[0] = v1x - s1 * dx;
  out[1] = v1y - s1 * dy;
  out[2] = v2x + s2 * dx;
  out[3] = v2y + s2 * dy;
  return -k * Math.sqrt(dd);
}

/**
 * Reflection off an immovable obstacle along the normal (nx, ny) (any length, pointing from the disc
 * towards the obstacle): v' = v - 2 (v.n)/(n.n) n, no square root, so a wall along an axis reflects
 * exactly. Writes [vx, vy] after into `out`; returns the approach speed (> 0 when it approached).
 */
export function reflectResponse(vx: number, vy: number, nx: number, ny: number, out: Float64Array): number {
  const vn = vx * nx + vy * ny;
  if (!(vn > 0)) {
    out[0] = vx;
    out[1] = vy;
    return 0;
  }
  const nn = nx * nx + ny * ny;
  const k = (2 * vn) / nn;
  out[0] = vx - k * nx;
  out[1] = vy - k * ny;
  return vn / Math.sqrt(nn);
}
