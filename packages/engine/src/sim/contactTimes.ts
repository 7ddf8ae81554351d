/**
 * Contact times with obstacles: when body s first touches a point, an end of a ray or segment, or
 * a line (the interior of rays and segments), from its motion alone; two bodies' times are
 * pairTimes.ts's. Pure queries of the state: nothing is offered or queued here (candidates.ts
 * keeps the earliest contact, predictor.ts decides which obstacles a body is tested against).
 */
import { discDiscTimeScaled, discLineCrossings } from "../physics/timeOfImpact.js";
import { CONTACT_BAND, END_INSIDE_SLACK, GRAZE_SLACK } from "../tolerances.js";
import { type Line, lineParameter, parameterOnLine } from "./obstacles.js";
import { PairTimes } from "./pairTimes.js";

const INF = Number.POSITIVE_INFINITY;
const INF_NEG = Number.NEGATIVE_INFINITY;
const sides = new Float64Array(2);

export class ContactTimes extends PairTimes {
  /**
   * The rounding of the gap |d|^2 - r^2 of body s (without friction: a friction motion never rests)
   * and a point at (px, py), now: 2 r times CONTACT_BAND of the magnitudes its centre and the point
   * carry (timeOfImpact.ts quarticContact: a pressed contact that cannot leave it is resting).
   */
  private pointBand(s: number, px: number, py: number): number {
    const b = this.store;
    const r = b.r[s] as number;
    const t = this.now;
    return (
      2 *
      r *
      CONTACT_BAND *
      (Math.abs(this.xAt(s, t)) + Math.abs(this.yAt(s, t)) + Math.abs(px) + Math.abs(py) + r)
    );
  }

  /**
   * Whether body s, touching the point (px, py) now and not pushed off it, stays in contact: its
   * contact with the point, solved from now with the motion it has, is now again (a contact the
   * prediction sees closing at third order, or not opening beyond rounding). A response that left
   * it so would find the same contact again at once, for ever (review of session 17: a disc crossing
   * a peg just above the speed that keeps it on, 65 events at one instant, then a Zeno error).
   */
  protected staysOnPoint(s: number, px: number, py: number): boolean {
    if ((this.store.mu[s] as number) > 0) return false;
    const t = this.now;
    return (
      this.pointContact(s, px, py, this.xAt(s, t), this.yAt(s, t), this.vxAt(s, t), this.vyAt(s, t), t) === 0
    );
  }

  /**
   * The contact time of body s with the point (px, py), local to `base`, from its position (x, y)
   * and velocity (vx, vy) at `base` and its motion's acceleration and end (pure query).
   */
  private pointContact(
    s: number,
    px: number,
    py: number,
    x: number,
    y: number,
    vx: number,
    vy: number,
    base: number,
  ): number {
    const b = this.store;
    const ax = b.mot[s * 8 + 5] as number;
    const ay = b.mot[s * 8 + 6] as number;
    const dx = x - px;
    const dy = y - py;
    if (onEdgePath(dx, dy, vx, vy, ax, ay, b.r[s] as number)) return INF;
    return discDiscTimeScaled(
      dx,
      dy,
      vx,
      vy,
      ax,
      ay,
      b.r[s] as number,
      this.now - base,
      (b.mot[s * 8 + 7] as number) - base,
      this.opt.quadraticFastPath,
      Math.abs(dx * vx) + Math.abs(dy * vy),
      Math.abs(dx * ax) + Math.abs(dy * ay),
      (b.mu[s] as number) > 0 ? INF_NEG : this.pointBand(s, px, py),
    );
  }

  /** Earliest contact of body s with a point at (px, py), or +Infinity. */
  protected pointTime(s: number, px: number, py: number): number {
    const m = this.store.mot;
    const t0 = m[s * 8 + 0] as number;
    const tau = this.pointContact(
      s,
      px,
      py,
      m[s * 8 + 1] as number,
      m[s * 8 + 2] as number,
      m[s * 8 + 3] as number,
      m[s * 8 + 4] as number,
      t0,
    );
    if (tau === INF) return INF;
    const t = t0 + tau;
    return Math.max(t, this.now);
  }

  /**
   * Earliest contact of body s with end 1 (x1, y1) or end 2 (x2, y2) of a ray or segment, or
   * +Infinity: pointTime's, unless that contact is not the end's: the path is straight and the
   * contact belongs to the interior (END_INSIDE_SLACK: the centre lies inside the solid part beyond
   * the slack, on a path that does not turn back) or is a graze (GRAZE_SLACK: the end lies r from the path's line, within the
   * rounding; a disc moving along a wall past its end). Either way the end is passed. Only on a
   * straight path (uniform, under friction, from rest, or curved by no more than a rounding) does
   * the first contact stand for all: its gap to the end is a quadratic in the distance travelled,
   * so after an entry from inside only the exit follows, and a graze is one all the way. A curved
   * path may come back from outside. One function with pointTime inlined into it, called from
   * testLine: split in two, V8 inlined them into testLine, and the gas took 1,300 more instructions
   * per collision at N = 10^3 (callgrind; this way 80 more, from 15,890).
   */
  protected endTime(s: number, line: Line, end: 1 | 2): number {
    const px = end === 1 ? line.x1 : line.x2;
    const py = end === 1 ? line.y1 : line.y2;
    const t = this.pointTime(s, px, py);
    if (t === INF) return INF;
    const b = this.store;
    const m = b.mot;
    const k = s * 8;
    const vx = m[k + 3] as number;
    const vy = m[k + 4] as number;
    const ax = m[k + 5] as number;
    const ay = m[k + 6] as number;
    const friction = (b.mu[s] as number) > 0;
    const uniform = ax === 0 && ay === 0;
    const fromRest = vx === 0 && vy === 0;
    const vv = Math.abs(vx) + Math.abs(vy);
    const aa = Math.abs(ax) + Math.abs(ay);
    if (!(uniform || friction || fromRest || Math.abs(vx * ay - vy * ax) <= END_INSIDE_SLACK * vv * aa))
      return t;
    const tc = t - (m[k] as number);
    const x0 = m[k + 1] as number;
    const y0 = m[k + 2] as number;
    const x = x0 + tc * (vx + 0.5 * ax * tc);
    const y = y0 + tc * (vy + 0.5 * ay * tc);
    const r = b.r[s] as number;
    // (the centre is rounded from the motion's origin and from the way travelled since)
    const scale = Math.abs(x0) + Math.abs(y0) + Math.abs(x) + Math.abs(y) + Math.abs(px) + Math.abs(py) + r;
    // the centre inside the solid part, on a path that does not turn back: the interior's contact
    const along = ((x - px) * line.ex + (y - py) * line.ey) / Math.sqrt(line.ee);
    const monotone = uniform || friction || fromRest || vx * ax + vy * ay >= 0;
    if (monotone && (end === 1 ? along : -along) > END_INSIDE_SLACK * scale) return INF;
    // a graze: the end lies r from the path's line, within the rounding of the positions
    let dx = vx + ax * tc;
    let dy = vy + ay * tc;
    if (dx === 0 && dy === 0) {
      dx = ax;
      dy = ay;
    }
    const h = Math.abs(dx * (py - y) - dy * (px - x)) / Math.sqrt(dx * dx + dy * dy);
    return Math.abs(h - r) <= GRAZE_SLACK * scale ? INF : t;
  }

  /**
   * Earliest contact of body s with the line (its interior for rays and segments; their end points
   * are tested as points). Returns the time, or +Infinity.
   */
  protected lineTime(s: number, line: Line): number {
    const b = this.store;
    const t0 = b.mot[s * 8 + 0] as number;
    const lo = this.now - t0;
    const hi = (b.mot[s * 8 + 7] as number) - t0;
    const x0 = b.mot[s * 8 + 1] as number;
    const y0 = b.mot[s * 8 + 2] as number;
    const vx = b.mot[s * 8 + 3] as number;
    const vy = b.mot[s * 8 + 4] as number;
    const ax = b.mot[s * 8 + 5] as number;
    const ay = b.mot[s * 8 + 6] as number;
    discLineCrossings(
      x0,
      y0,
      vx,
      vy,
      ax,
      ay,
      line.x1,
      line.y1,
      line.nx,
      line.ny,
      b.r[s] as number,
      lo,
      hi,
      sides,
    );
    let best = INF;
    for (let k = 0; k < 2; k++) {
      const tau = sides[k] as number;
      if (tau >= best) continue;
      if (line.kind !== "line") {
        // Where the disc is at the contact: a contact under way is now (its crossing of the
        // infinite line may lie long before, beyond the end of a ray or segment).
        const tc = Math.max(tau, lo);
        const lambda = lineParameter(line, x0 + tc * (vx + 0.5 * ax * tc), y0 + tc * (vy + 0.5 * ay * tc));
        if (!parameterOnLine(line.kind, lambda)) continue;
      }
      best = tau;
    }
    if (best === INF) return INF;
    const t = t0 + best;
    return Math.max(t, this.now);
  }
}

/**
 * Whether a point at (-dx, -dy) from the centre of a disc of radius r lies exactly on the line its
 * edge moves along: the motion is parallel to an axis (velocity and acceleration both) and the
 * point is r from the centre across it, exactly. The gap |d|^2 - r^2 is then the square of the
 * distance along the path, which touches 0 where the disc passes the point and never crosses it:
 * no contact (a disc sliding along a channel of segments exactly its diameter wide, past a wall's
 * end point). Only for an accelerated motion: the quartic solve saw the rounded square, whose
 * double root it certified at every prediction (6-8 times the cost of an event) and, where the
 * rounding dipped below 0, reported a contact whose tiny impulse set the disc bouncing between the
 * two walls it touched, a Zeno error at once. Without acceleration the closed form of the
 * quadratic decides as before.
 */
function onEdgePath(
  dx: number,
  dy: number,
  vx: number,
  vy: number,
  ax: number,
  ay: number,
  r: number,
): boolean {
  if (ax === 0 && ay === 0) return false;
  return (vx === 0 && ax === 0 && Math.abs(dx) === r) || (vy === 0 && ay === 0 && Math.abs(dy) === r);
}
