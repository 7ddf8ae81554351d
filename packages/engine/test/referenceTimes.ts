/**
 * Test support: the contact times of the reference simulator (referenceWorld.ts), each from a
 * body's motion alone, through the same pure kernels as the World (physics/timeOfImpact.ts): of two
 * bodies, of a body and a point (also a ray's or segment's end), of a body and a line's length. Each
 * gives the absolute time of the next contact at or after `now`, a contact under way counting as
 * now, or INF when there is none before a body's motion ends.
 */
import { positionAt, velocityAt } from "../src/physics/motion.js";
import { discDiscTimeScaled, discLineCrossings } from "../src/physics/timeOfImpact.js";
import { type Line, lineParameter, parameterOnLine } from "../src/sim/obstacles.js";
import { CONTACT_BAND } from "../src/tolerances.js";

const INF = Number.POSITIVE_INFINITY;

/** A body of the reference: its motion since t0 (as the World's), its radius, mass and friction. */
export interface RefBody {
  id: string;
  t0: number;
  x0: number;
  y0: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
  tEnd: number;
  r: number;
  m: number;
  mu: number;
}

/** Position of a body at time t (t within its motion). */
export function refPos(b: RefBody, t: number): [number, number] {
  return [positionAt(b.t0, b.x0, b.vx, b.ax, t), positionAt(b.t0, b.y0, b.vy, b.ay, t)];
}

/** Velocity of a body at time t (t within its motion). */
export function refVelo(b: RefBody, t: number): [number, number] {
  return [velocityAt(b.t0, b.vx, b.ax, t), velocityAt(b.t0, b.vy, b.ay, t)];
}

/** When two bodies next touch, from `now` on (INF: never). */
export function refPairTime(s: RefBody, o: RefBody, now: number): number {
  const tb = Math.max(s.t0, o.t0);
  const [xs, ys] = refPos(s, tb);
  const [xo, yo] = refPos(o, tb);
  const [vxs, vys] = refVelo(s, tb);
  const [vxo, vyo] = refVelo(o, tb);
  const hi = Math.min(s.tEnd, o.tEnd) - tb;
  const tau = discDiscTimeScaled(
    xo - xs,
    yo - ys,
    vxo - vxs,
    vyo - vys,
    o.ax - s.ax,
    o.ay - s.ay,
    s.r + o.r,
    now - tb,
    hi,
    true,
    Math.abs(xo - xs) * (Math.abs(vxs) + Math.abs(vxo)) + Math.abs(yo - ys) * (Math.abs(vys) + Math.abs(vyo)),
    Math.abs(xo - xs) * (Math.abs(s.ax) + Math.abs(o.ax)) +
      Math.abs(yo - ys) * (Math.abs(s.ay) + Math.abs(o.ay)),
    Number.NEGATIVE_INFINITY,
  );
  return tau === INF ? INF : Math.max(now, tb + tau);
}

/** When a body next touches the point (px, py), from `now` on (INF: never). */
export function refPointTime(b: RefBody, px: number, py: number, now: number): number {
  const dx = b.x0 - px;
  const dy = b.y0 - py;
  // without friction, a pressed contact within the gap's rounding is resting (CONTACT_BAND)
  const [x, y] = refPos(b, now);
  const band =
    b.mu > 0
      ? Number.NEGATIVE_INFINITY
      : 2 * b.r * CONTACT_BAND * (Math.abs(x) + Math.abs(y) + Math.abs(px) + Math.abs(py) + b.r);
  const tau = discDiscTimeScaled(
    dx,
    dy,
    b.vx,
    b.vy,
    b.ax,
    b.ay,
    b.r,
    now - b.t0,
    b.tEnd - b.t0,
    true,
    Math.abs(dx * b.vx) + Math.abs(dy * b.vy),
    Math.abs(dx * b.ax) + Math.abs(dy * b.ay),
    band,
  );
  return tau === INF ? INF : Math.max(now, b.t0 + tau);
}

/** When a body next touches the line (its length; ends: refPointTime), from `now` on (INF: never). */
export function refLineTime(b: RefBody, line: Line, now: number): number {
  const out = new Float64Array(2);
  const lo = now - b.t0;
  discLineCrossings(
    b.x0,
    b.y0,
    b.vx,
    b.vy,
    b.ax,
    b.ay,
    line.x1,
    line.y1,
    line.nx,
    line.ny,
    b.r,
    lo,
    b.tEnd - b.t0,
    out,
  );
  let best = INF;
  for (const tau of out) {
    if (tau >= best) continue;
    const tc = Math.max(tau, lo); // a contact under way is now
    const x = b.x0 + tc * (b.vx + 0.5 * b.ax * tc);
    const y = b.y0 + tc * (b.vy + 0.5 * b.ay * tc);
    if (line.kind !== "line" && !parameterOnLine(line.kind, lineParameter(line, x, y))) continue;
    best = tau;
  }
  return best === INF ? INF : Math.max(now, b.t0 + best);
}
