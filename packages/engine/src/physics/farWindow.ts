/**
 * Where in the far part of an accelerated pair's path the pair can touch (pure; no allocation): the
 * times in [from, to] at which the relative position d(tau) = d + u tau + w tau^2 / 2 is within
 * 2 R of zero in both components, along the unit vector h of w and across it. farContact.ts solves
 * the contact only there, re-anchored at each window's start.
 *
 * Across w the separation is a line t(tau); along w a convex parabola s(tau). |t| <= 2R holds on one
 * interval; |s| <= 2R on at most two (s <= 2R on one interval, minus the stretch where s < -2R). So
 * there are at most two windows, and in each |d| <= 2 sqrt(2) R throughout: a quartic anchored at a
 * window's start has terms of size R^2 there, whatever the path did before. The bound 2 R (not R)
 * leaves a margin of R for the rounding of s and t (about UNIT_ROUNDOFF times the path's span M):
 * every time at which |d| <= R lies in a window while M < 1e14 R; beyond that positions themselves
 * cannot place a contact. Most far pairs (a disc falling past the pins of a board) have no window
 * and cost a few multiplications.
 */

/**
 * The windows in [from, to], in order, into out (out[0], out[1]) and (out[2], out[3]); returns their
 * number (0, 1 or 2).
 */
export function farWindows(
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
): number {
  let a = from;
  let b = to;
  const bound = 2 * R;
  // The unit vector h of w, scaled first so that a tiny w does not underflow to a zero norm.
  const big = Math.max(Math.abs(wx), Math.abs(wy));
  if (big === 0) return straightWindow(dx, dy, ux, uy, bound, a, b, out);
  const sx = wx / big;
  const sy = wy / big;
  const norm = Math.sqrt(sx * sx + sy * sy);
  const hx = sx / norm;
  const hy = sy / norm;
  const W = big * norm;
  // Across w: t(tau) = t0 + t1 tau, |t| <= bound on one interval (or always, or never).
  const t0 = dx * hy - dy * hx;
  const t1 = ux * hy - uy * hx;
  if (t1 === 0) {
    if (Math.abs(t0) > bound) return 0;
  } else {
    const e1 = (-bound - t0) / t1;
    const e2 = (bound - t0) / t1;
    a = Math.max(a, Math.min(e1, e2));
    b = Math.min(b, Math.max(e1, e2));
    if (!(a <= b)) return 0;
  }
  // Along w: s(tau) = s0 + s1 tau + (W / 2) tau^2.
  const s0 = dx * hx + dy * hy;
  const s1 = ux * hx + uy * hy;
  const s2 = 0.5 * W;
  if (!parabolaBelow(s0 - bound, s1, s2)) return 0;
  a = Math.max(a, root1);
  b = Math.min(b, root2);
  if (!(a <= b)) return 0;
  // Cut out the stretch where s < -bound (deep on the far side), if any.
  let n = 0;
  if (parabolaBelow(s0 + bound, s1, s2) && root1 < root2) {
    const cut1 = root1;
    const cut2 = root2;
    if (a <= cut1) {
      out[0] = a;
      out[1] = Math.min(b, cut1);
      n = 1;
    }
    if (cut2 <= b) {
      out[2 * n] = Math.max(a, cut2);
      out[2 * n + 1] = b;
      n++;
    }
    return n;
  }
  out[0] = a;
  out[1] = b;
  return 1;
}

/** Without acceleration: |d + u tau| <= bound within the interval where its component along u is. */
function straightWindow(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  bound: number,
  from: number,
  to: number,
  out: Float64Array,
): number {
  const big = Math.max(Math.abs(ux), Math.abs(uy));
  let a = from;
  let b = to;
  if (big === 0) {
    if (Math.abs(dx) > bound || Math.abs(dy) > bound) return 0;
  } else {
    const sx = ux / big;
    const sy = uy / big;
    const norm = Math.sqrt(sx * sx + sy * sy);
    const hx = sx / norm;
    const hy = sy / norm;
    if (Math.abs(dx * hy - dy * hx) > bound) return 0;
    const s0 = dx * hx + dy * hy;
    const speed = big * norm;
    a = Math.max(a, (-bound - s0) / speed);
    b = Math.min(b, (bound - s0) / speed);
    if (!(a <= b)) return 0;
  }
  out[0] = a;
  out[1] = b;
  return 1;
}

let root1 = 0;
let root2 = 0;

/**
 * Whether c0 + c1 tau + c2 tau^2 (c2 > 0) is <= 0 somewhere; if so the interval where it is, in
 * (root1, root2), from the closed form without cancellation.
 */
function parabolaBelow(c0: number, c1: number, c2: number): boolean {
  const disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) return false;
  const q = c1 >= 0 ? -0.5 * (c1 + Math.sqrt(disc)) : -0.5 * (c1 - Math.sqrt(disc));
  if (q === 0) {
    root1 = 0;
    root2 = 0;
    return true;
  }
  const r1 = q / c2;
  const r2 = c0 / q;
  root1 = Math.min(r1, r2);
  root2 = Math.max(r1, r2);
  return true;
}
