/**
 * Closed-form motion of a disc between two events (pure functions).
 *
 * A motion is (t0, p0, v0, a, tEnd): p(t) = p0 + (t - t0) * (v0 + (t - t0) * a / 2), valid for
 * t0 <= t <= tEnd. With friction the acceleration is a = -mu*g*unit(v0) and the disc stops at
 * tEnd = t0 + |v0| / (mu*g); otherwise a is the gravity field and tEnd is +Infinity.
 * Every part of chapgame (World, Timeline, editor) evaluates motion through these functions, so the
 * same motion gives the same bits everywhere. Only + - * / and sqrt are used (cross-browser exact).
 */

/** One coordinate of the position at time t of a motion that started at t0. */
export function positionAt(t0: number, p0: number, v0: number, a: number, t: number): number {
  const dt = t - t0;
  return p0 + dt * (v0 + 0.5 * a * dt);
}

/** One coordinate of the velocity at time t of a motion that started at t0. */
export function velocityAt(t0: number, v0: number, a: number, t: number): number {
  return v0 + a * (t - t0);
}

/** Acceleration and end time of a motion that starts at t0 with velocity (vx, vy). */
export interface MotionLaw {
  ax: number;
  ay: number;
  /** When the motion ends by itself (friction stop), or +Infinity. */
  tEnd: number;
}

/**
 * The motion law of a disc with friction coefficient mu in a scene with friction field g and
 * gravity (gx, gy). The caller guarantees that friction and gravity are not both active.
 * A disc at rest under friction has no acceleration and no end.
 */
export function motionLaw(
  t0: number,
  vx: number,
  vy: number,
  mu: number,
  g: number,
  gx: number,
  gy: number,
  out: MotionLaw,
): MotionLaw {
  const decel = mu * g;
  if (decel > 0) {
    const speed = Math.sqrt(vx * vx + vy * vy);
    if (speed === 0) {
      out.ax = 0;
      out.ay = 0;
      out.tEnd = Number.POSITIVE_INFINITY;
    } else {
      out.ax = (-decel * vx) / speed;
      out.ay = (-decel * vy) / speed;
      out.tEnd = t0 + speed / decel;
    }
  } else {
    out.ax = gx;
    out.ay = gy;
    out.tEnd = Number.POSITIVE_INFINITY;
  }
  return out;
}
