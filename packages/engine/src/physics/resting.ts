/**
 * pressedInto: whether a disc touching an obstacle, not approaching it, stays pressed against it by
 * its acceleration (a resting contact, which the exact model cannot continue: it would take
 * infinitely many bounces). Pure; the simulator refuses such a contact with a SimulationError.
 *
 * With the contact normal n from the disc's centre towards the obstacle (not normalised), velocity
 * v and acceleration a:
 * - a flat contact (a line, or the side of a ray or segment) stays closed when a·n > 0;
 * - a round contact (a point, or the end of a ray or segment: n is the centre-to-point vector, of
 *   length r) stays closed only when a·n > |v|², since the gap's second derivative there is
 *   2(|v|² − a·n): a disc fast enough over a point flies on, as a thrown ball passes over a post
 *   (audit of session 15: such a flyover under gravity was refused as resting);
 * - a friction motion never rests: its acceleration points against its velocity, so a disc that is
 *   not approaching an obstacle never turns towards it (a disc gliding along a cushion under
 *   friction past its end was refused as resting).
 */
export function pressedInto(
  vx: number,
  vy: number,
  ax: number,
  ay: number,
  nx: number,
  ny: number,
  round: boolean,
  friction: boolean,
): boolean {
  if (friction) return false;
  const an = ax * nx + ay * ny;
  return round ? an > vx * vx + vy * vy : an > 0;
}
