/**
 * The geometry of a contact at the moment it is processed, a layer of the World under Simulator:
 * where a disc touches a line, a ray's or segment's end, or a point, and the normal there
 * (obstacleContact); the reflection off an obstacle with the resting-contact refusal (reflectOff);
 * and the check that doubles still place a contact at all (requireResolved and the obstacle case:
 * physics/resolution.ts), which throws a SimulationError naming the participants before anything
 * changes. `contact` and `vel` are the scratch the processing shares with these methods.
 */
import { contactResolved, unresolvedContact } from "../physics/resolution.js";
import { reflectResponse } from "../physics/response.js";
import { pressedInto } from "../physics/resting.js";
import { EV_LINE } from "./bodyStore.js";
import { SimulationError } from "./errors.js";
import { idBefore } from "./idOrder.js";
import type { Line, Point } from "./obstacles.js";
import { quoteId } from "./refusalText.js";
import { ZenoGuard } from "./zenoGuard.js";

/** Velocities out of a response: (vx, vy) of the body, then of its partner. */
export const vel: Float64Array = new Float64Array(4);
/** Obstacle contact scratch: normal (nx, ny, not normalised) and contact point (x, y). */
export const contact: Float64Array = new Float64Array(4);

export class ContactGeometry extends ZenoGuard {
  /**
   * Throws the SimulationError of a contact the doubles cannot place (physics/resolution.ts) when
   * bodies s and o, centred at (xs, ys) and (xo, yo), are not within it of touching; else nothing.
   */
  protected requireResolved(s: number, o: number, xs: number, ys: number, xo: number, yo: number): void {
    const b = this.store;
    const dx = xo - xs;
    const dy = yo - ys;
    const d = Math.sqrt(dx * dx + dy * dy);
    const D = (b.r[s] as number) + (b.r[o] as number);
    if (contactResolved(d, D)) return;
    // in the canonical order of the log (idOrder.ts)
    const first = idBefore(
      b.idKey[s] as number,
      b.idKey[o] as number,
      b.ids[s] as string,
      b.ids[o] as string,
    );
    const ids = first ? [b.ids[s] as string, b.ids[o] as string] : [b.ids[o] as string, b.ids[s] as string];
    const t = this.now;
    const message = unresolvedContact({
      what: `body ${quoteId(ids[0] as string)} meets body ${quoteId(ids[1] as string)}`,
      between: "the centres",
      t,
      d,
      D,
      coordinate: Math.max(
        Math.abs(xs),
        Math.abs(ys),
        Math.abs(xo),
        Math.abs(yo),
        this.startPlace(s),
        this.startPlace(o),
      ),
      speed: Math.max(this.speedAt(s, t), this.speedAt(o, t)),
      start: this.farStart(this.store.mot[s * 8] as number, this.store.mot[o * 8] as number),
    });
    throw new SimulationError(message, t, ids);
  }

  /** The same for body s, centred at (x, y), at distance d from obstacle `id` (a line when `line`) whose point (px, py) is nearest it. */
  private requireResolvedObstacle(
    s: number,
    id: string,
    line: boolean,
    x: number,
    y: number,
    d: number,
    px: number,
    py: number,
  ): void {
    const r = this.store.r[s] as number;
    if (contactResolved(d, r)) return;
    const who = this.store.ids[s] as string;
    const t = this.now;
    const message = unresolvedContact({
      what: `body ${quoteId(who)} meets ${quoteId(id)}`,
      between: line ? "the centre and the line" : "the centre and the point",
      t,
      d,
      D: r,
      coordinate: Math.max(Math.abs(x), Math.abs(y), Math.abs(px), Math.abs(py), this.startPlace(s)),
      speed: this.speedAt(s, t),
      start: this.store.mot[s * 8] as number,
    });
    throw new SimulationError(message, t, [who, id]);
  }

  /** The size of body s's motion's starting position (x0, y0), from which its place is evaluated. */
  private startPlace(s: number): number {
    const m = this.store.mot;
    return Math.max(Math.abs(m[s * 8 + 1] as number), Math.abs(m[s * 8 + 2] as number));
  }

  /** Of two motions' starts t0, the one farther from 0. */
  private farStart(a: number, b: number): number {
    return Math.abs(a) >= Math.abs(b) ? a : b;
  }

  private speedAt(s: number, t: number): number {
    const vx = this.vxAt(s, t);
    const vy = this.vyAt(s, t);
    return Math.sqrt(vx * vx + vy * vy);
  }

  /**
   * Contact of body s, centred at (x, y), with an obstacle (kind, index, aux as in the prediction):
   * writes the normal from the disc towards the obstacle (not normalised) and the contact point to
   * `contact`; returns the obstacle's id.
   */
  protected obstacleContact(
    s: number,
    kind: number,
    index: number,
    aux: number,
    x: number,
    y: number,
  ): string {
    if (kind === EV_LINE && aux === 0) {
      const line = this.lineList[index] as Line;
      // Unnormalised normal (-ey, ex), oriented from the disc towards the line.
      const side = line.nx * (x - line.x1) + line.ny * (y - line.y1);
      const nx = side > 0 ? line.ey : -line.ey;
      const ny = side > 0 ? -line.ex : line.ex;
      const len = Math.sqrt(line.ee);
      const r = this.store.r[s] as number;
      // side: the signed distance (unit normal); its foot on the line, for the message's scale
      const dist = side < 0 ? -side : side;
      if (!contactResolved(dist, r))
        this.requireResolvedObstacle(s, line.id, true, x, y, dist, line.x1, line.y1);
      contact[0] = nx;
      contact[1] = ny;
      contact[2] = x + (r * nx) / len;
      contact[3] = y + (r * ny) / len;
      return line.id;
    }
    let px: number;
    let py: number;
    let id: string;
    if (kind === EV_LINE) {
      const line = this.lineList[index] as Line;
      id = line.id;
      px = aux === 1 ? line.x1 : line.x2;
      py = aux === 1 ? line.y1 : line.y2;
    } else {
      const point = this.pointList[index] as Point;
      id = point.id;
      px = point.x;
      py = point.y;
    }
    contact[0] = px - x;
    contact[1] = py - y;
    contact[2] = px;
    contact[3] = py;
    const dist = Math.sqrt((px - x) * (px - x) + (py - y) * (py - y));
    if (!contactResolved(dist, this.store.r[s] as number))
      this.requireResolvedObstacle(s, id, kind === EV_LINE, x, y, dist, px, py);
    return id;
  }

  /**
   * Reflect body s's velocity now off normal (nx, ny) into `vel`; returns the approach speed.
   * Throws when the body rests against the obstacle under an acceleration pressing it there
   * (physics/resting.ts), or, not pushed off a round contact, stays on it (staysOnPoint). The contact is slot s's pending event: a point or an end of a ray or
   * segment is round, a line's side flat (read here, so processObstacle's hot path stays exactly as
   * it was; an A/B of the longer call there read 2-4 % slower on the gas, within this host's noise).
   */
  protected reflectOff(s: number, otherId: string, nx: number, ny: number): number {
    const t = this.now;
    const px = contact[2] as number; // a round contact's point (obstacleContact)
    const py = contact[3] as number;
    const round = (this.store.evKind[s] as number) !== EV_LINE || (this.store.evAux[s] as number) !== 0;
    const vx = this.vxAt(s, t);
    const vy = this.vyAt(s, t);
    const approach = reflectResponse(vx, vy, nx, ny, vel);
    const mot = this.store.mot;
    const friction = (this.store.mu[s] as number) > 0;
    const ax = mot[s * 8 + 5] as number;
    const ay = mot[s * 8 + 6] as number;
    if (
      approach <= 0 &&
      (pressedInto(vx, vy, ax, ay, nx, ny, round, friction) || (round && this.staysOnPoint(s, px, py)))
    ) {
      throw new SimulationError(
        `body ${quoteId(this.store.ids[s] as string)} rests against ${quoteId(otherId)} under an acceleration at t=${t}: resting contact is not supported (it would take infinitely many bounces): place the body a little apart from ${quoteId(otherId)} (it then bounces, elastically), or give it no acceleration towards it`,
        t,
        [this.store.ids[s] as string, otherId],
      );
    }
    return approach;
  }
}
