/**
 * A cheap, conservative window for the far part of an accelerated pair's path (pure; no allocation):
 * the times in [from, to] at which the relative position d(tau) = d + u tau + w tau^2 / 2 can be
 * within the contact distance R. farContact.ts searches the exact contact only there, so the many
 * far pairs that never come near (a disc falling past the pins of a board under gravity) cost a few
 * multiplications instead of a cubic and a quartic.
 *
 * Along the unit vector h of w the separation is a convex parabola s(tau), across it a line t(tau);
 * |d| <= R needs s <= R and |t| <= R, each a single interval of time, found in closed form. The
 * bound used is 2 R, which leaves a margin of R for the rounding of s and t (about UNIT_ROUNDOFF
 * times the path's span M): the window can only be too wide, never too narrow, while M < 1e14 R;
 * beyond that positions themselves cannot place a contact.
 */

/**
 * Narrows [from, to] to where the pair can touch. Returns false when it cannot touch there;
 * otherwise true with the window in out[0], out[1] (from <= out[0] <= out[1] <= to).
 */
export function farWindow(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  from: number,
  to: number,
  out: Float64Array,
): boolean {
  let a = from;
  let b = to;
  const W = Math.sqrt(wx * wx + wy * wy);
  if (W > 0) {
    const hx = wx / W;
    const hy = wy / W;
    const bound = 2 * R;
    // Across w: t(tau) = t0 + t1 tau, |t| <= bound on one interval (or always, or never).
    const t0 = dx * hy - dy * hx;
    const t1 = ux * hy - uy * hx;
    if (t1 === 0) {
      if (Math.abs(t0) > bound) return false;
    } else {
      const e1 = (-bound - t0) / t1;
      const e2 = (bound - t0) / t1;
      a = Math.max(a, Math.min(e1, e2));
      b = Math.min(b, Math.max(e1, e2));
      if (!(a <= b)) return false;
    }
    // Along w: s(tau) = s0 + s1 tau + (W / 2) tau^2 <= bound between the roots of a convex quadratic.
    const s0 = dx * hx + dy * hy - bound;
    const s1 = ux * hx + uy * hy;
    const s2 = 0.5 * W;
    const disc = s1 * s1 - 4 * s2 * s0;
    if (disc < 0) return false;
    const q = s1 >= 0 ? -0.5 * (s1 + Math.sqrt(disc)) : -0.5 * (s1 - Math.sqrt(disc));
    let r1 = q / s2;
    let r2 = q === 0 ? 0 : s0 / q;
    if (r1 > r2) {
      const t = r1;
      r1 = r2;
      r2 = t;
    }
    a = Math.max(a, r1);
    b = Math.min(b, r2);
    if (!(a <= b)) return false;
  }
  out[0] = a;
  out[1] = b;
  return true;
}
