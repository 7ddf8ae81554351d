/**
 * MotionTable: the Timeline's copy of every body's current motion, indexed by body number (one number
 * per body incarnation: re-adding a removed id gives a new number). A motion is exactly the World's
 * (t0, x0, y0, vx0, vy0, ax, ay, tEnd) plus r, m, mu, and is evaluated with the same functions
 * (physics/motion.ts), so positions agree with `World.body(id, t)` bit for bit. At an event a body is
 * rebased the way the World does it: t0 = te, p0 = position at te, v0 = the new velocity, a and tEnd
 * from motionLaw.
 */
import { type MotionLaw, motionLaw, positionAt, velocityAt } from "../physics/motion.js";
import type { BodyMotion, BodyState } from "../sim/types.js";

/** Float64 slots per body: t0, x0, y0, vx0, vy0, ax, ay, tEnd, r, m, mu. */
export const STRIDE = 11;
const INF = Number.POSITIVE_INFINITY;
const law: MotionLaw = { ax: 0, ay: 0, tEnd: INF };

export class MotionTable {
  data: Float64Array;

  constructor(capacity = 16) {
    this.data = new Float64Array(capacity * STRIDE);
  }

  /** Make room for body numbers < n. */
  ensure(n: number): void {
    if (n * STRIDE <= this.data.length) return;
    let cap = this.data.length / STRIDE || 16;
    while (cap < n) cap *= 2;
    const d = new Float64Array(cap * STRIDE);
    d.set(this.data);
    this.data = d;
  }

  /** Set body i's radius, mass and friction coefficient (before start()). */
  setProps(i: number, r: number, m: number, mu: number): void {
    const o = i * STRIDE;
    this.data[o + 8] = r;
    this.data[o + 9] = m;
    this.data[o + 10] = mu;
  }

  /**
   * Set body i to the World's own motion of it (World.motion) and its r, m, mu: exactly what the World
   * computes from, whether an edit restarted the motion or kept it (an updateBody that changes
   * nothing keeps it; restarting the table's copy there made keyframes and reads drift from the World).
   */
  setFromWorld(i: number, m: BodyMotion, s: BodyState): void {
    this.setProps(i, s.r, s.m, s.mu);
    const d = this.data;
    const o = i * STRIDE;
    d[o] = m.t0;
    d[o + 1] = m.x0;
    d[o + 2] = m.y0;
    d[o + 3] = m.vx;
    d[o + 4] = m.vy;
    d[o + 5] = m.ax;
    d[o + 6] = m.ay;
    d[o + 7] = m.tStop;
  }

  /** Start a new motion of body i at t from (x, y) with (vx, vy). */
  start(
    i: number,
    t: number,
    x: number,
    y: number,
    vx: number,
    vy: number,
    g: number,
    gx: number,
    gy: number,
  ): void {
    const d = this.data;
    const o = i * STRIDE;
    motionLaw(t, vx, vy, d[o + 10] as number, g, gx, gy, law);
    d[o] = t;
    d[o + 1] = x;
    d[o + 2] = y;
    d[o + 3] = vx;
    d[o + 4] = vy;
    d[o + 5] = law.ax;
    d[o + 6] = law.ay;
    d[o + 7] = law.tEnd;
  }

  /** Rebase body i at event time t with its new velocity (as the World does at an event). */
  rebase(i: number, t: number, vx: number, vy: number, g: number, gx: number, gy: number): void {
    this.start(i, t, this.x(i, t), this.y(i, t), vx, vy, g, gx, gy);
  }

  x(i: number, t: number): number {
    const d = this.data;
    const o = i * STRIDE;
    const tEnd = d[o + 7] as number;
    return positionAt(
      d[o] as number,
      d[o + 1] as number,
      d[o + 3] as number,
      d[o + 5] as number,
      Math.min(t, tEnd),
    );
  }

  y(i: number, t: number): number {
    const d = this.data;
    const o = i * STRIDE;
    const tEnd = d[o + 7] as number;
    return positionAt(
      d[o] as number,
      d[o + 2] as number,
      d[o + 4] as number,
      d[o + 6] as number,
      Math.min(t, tEnd),
    );
  }

  vx(i: number, t: number): number {
    const d = this.data;
    const o = i * STRIDE;
    return t < (d[o + 7] as number)
      ? velocityAt(d[o] as number, d[o + 3] as number, d[o + 5] as number, t)
      : 0;
  }

  vy(i: number, t: number): number {
    const d = this.data;
    const o = i * STRIDE;
    return t < (d[o + 7] as number)
      ? velocityAt(d[o] as number, d[o + 4] as number, d[o + 6] as number, t)
      : 0;
  }

  r(i: number): number {
    return this.data[i * STRIDE + 8] as number;
  }

  m(i: number): number {
    return this.data[i * STRIDE + 9] as number;
  }

  mu(i: number): number {
    return this.data[i * STRIDE + 10] as number;
  }

  /** The state of body i at t, exactly as World.body(id, t) computes it. */
  state(i: number, id: string, t: number): BodyState {
    const d = this.data;
    const o = i * STRIDE;
    const moving = t < (d[o + 7] as number);
    return {
      id,
      x: this.x(i, t),
      y: this.y(i, t),
      vx: this.vx(i, t),
      vy: this.vy(i, t),
      ax: moving ? (d[o + 5] as number) : 0,
      ay: moving ? (d[o + 6] as number) : 0,
      r: d[o + 8] as number,
      m: d[o + 9] as number,
      mu: d[o + 10] as number,
    };
  }
}
