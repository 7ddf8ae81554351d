/**
 * Processing: the next queued item (a cell crossing, a stale prediction, or a collision or stop,
 * which the Zeno watch (zenoWatch.ts) counts, which changes motions and is reported), and a
 * look-ahead at the next event's time that changes nothing (its internal work is undone through
 * peek.ts).
 */

import { contactResolved, unresolvedContact } from "../physics/resolution.js";
import { discDiscResponse, impulseMagnitude, reflectResponse } from "../physics/response.js";
import { pressedInto } from "../physics/resting.js";
import { EV_BODY, EV_LINE, EV_POINT, EV_STOP } from "./bodyStore.js";
import { SimulationError } from "./errors.js";
import { idBefore } from "./idOrder.js";
import type { Line, Point } from "./obstacles.js";
import { PeekLog } from "./peek.js";
import type { WorldEvent } from "./types.js";
import { ZenoGuard } from "./zenoGuard.js";

const INF = Number.POSITIVE_INFINITY;
const vel = new Float64Array(4);
/** Obstacle contact scratch: normal (nx, ny, not normalised) and contact point (x, y). */
const contact = new Float64Array(4);
export class Simulator extends ZenoGuard {
  // ---- processing ---------------------------------------------------------------------------

  /**
   * Process the next queued item if its time is <= untilTime. Returns 1 when a counted event
   * (collision or stop) was processed and reported, 0 for internal work (cell crossing or stale
   * prediction), -1 when nothing is left before untilTime.
   */
  protected stepOnce(untilTime: number, onEvent: ((e: WorldEvent) => void) | undefined): number {
    const s = this.heap.peek();
    if (s < 0) return -1;
    const t = this.heap.peekKey();
    if (t > untilTime) return -1;
    const before = this.now;
    if (t > this.now) this.now = t;
    const b = this.store;
    if ((b.crossTime[s] as number) <= (b.evTime[s] as number)) {
      this.processCrossing(s);
      return 0;
    }
    const kind = b.evKind[s] as number;
    if (kind === EV_BODY) {
      const o = b.evOther[s] as number;
      if (b.version[o] !== b.evOtherVersion[s]) {
        this.predict(s);
        return 0;
      }
    }
    // An obstacle event guards itself, after the response's own refusal (a resting contact): a
    // refused event counts nothing, so retrying gives the same message.
    if (kind === EV_BODY) {
      this.guardZeno(before, s, kind);
      this.processBodyBody(s, b.evOther[s] as number);
    } else if (kind === EV_STOP) {
      this.guardZeno(before, s, kind);
      this.processStop(s);
    } else this.processObstacle(s, kind, b.evOther[s] as number, b.evAux[s] as number, before);
    onEvent?.(this.ev as WorldEvent); // filled in by the process method: its kind and b agree
    return 1;
  }

  /**
   * Time of the next collision or stop (+Infinity when none), found without moving the world: the
   * internal items before it are processed in place exactly as stepOnce would process them, logged,
   * and undone (peek.ts), and the time restored. Throws what processing that event would throw (a
   * Zeno state, a resting contact), also changing nothing. Needs up-to-date predictions (!dirty).
   * Cost: O(1) per internal item before the event, not O(N).
   */
  protected peekEventTime(): number {
    const b = this.store;
    const log = this.peekLog;
    const now = this.now;
    log.begin(b.capacity);
    try {
      // Ends at the next collision or stop (or an empty queue): the internal items before it are
      // finitely many, as in World.advance (a body crosses finitely many cells before its next event;
      // a prediction goes stale at most once per event of its partner).
      for (;;) {
        const s = this.heap.peek();
        if (s < 0) return INF;
        const t = this.heap.peekKey();
        const before = this.now;
        if (t > this.now) this.now = t;
        if ((b.crossTime[s] as number) <= (b.evTime[s] as number)) {
          log.save(b, s, t);
          log.recordMove(this.grid, s);
          this.processCrossing(s);
          continue;
        }
        const kind = b.evKind[s] as number;
        if (kind === EV_BODY && b.version[b.evOther[s] as number] !== b.evOtherVersion[s]) {
          log.save(b, s, t);
          this.predict(s);
          continue;
        }
        this.checkEvent(s, kind, before);
        return this.now;
      }
    } finally {
      log.undo(b, this.grid, this.heap);
      this.now = now;
    }
  }

  private readonly peekLog = new PeekLog();

  /** Throw what processing slot s's event (of this kind, now; the time before it `before`) would throw; change nothing. */
  private checkEvent(s: number, kind: number, before: number): void {
    const watch = this.zeno.save();
    try {
      // The same order as stepOnce: an obstacle's resting refusal comes before the Zeno guard.
      if (kind === EV_LINE || kind === EV_POINT) {
        const b = this.store;
        const t = this.now;
        const id = this.obstacleContact(
          s,
          kind,
          b.evOther[s] as number,
          b.evAux[s] as number,
          this.xAt(s, t),
          this.yAt(s, t),
        );
        this.reflectOff(s, id, contact[0] as number, contact[1] as number);
      } else if (kind === EV_BODY) {
        const o = this.store.evOther[s] as number;
        const t = this.now;
        this.requireResolved(s, o, this.xAt(s, t), this.yAt(s, t), this.xAt(o, t), this.yAt(o, t));
      }
      this.guardZeno(before, s, kind);
    } finally {
      this.zeno.load(watch);
    }
  }

  protected processBodyBody(s: number, o: number): void {
    const b = this.store;
    // Canonical order: `a` is the body with the smaller id, so the arithmetic is the same whichever body held the event.
    const sFirst = idBefore(
      b.idKey[s] as number,
      b.idKey[o] as number,
      b.ids[s] as string,
      b.ids[o] as string,
    );
    const p = sFirst ? s : o;
    const q = sFirst ? o : s;
    const t = this.now;
    const xp = this.xAt(p, t);
    const yp = this.yAt(p, t);
    const xq = this.xAt(q, t);
    const yq = this.yAt(q, t);
    const vxp = this.vxAt(p, t);
    const vyp = this.vyAt(p, t);
    const vxq = this.vxAt(q, t);
    const vyq = this.vyAt(q, t);
    const mp = b.m[p] as number;
    const mq = b.m[q] as number;
    const dx = xq - xp;
    const dy = yq - yp;
    const d = Math.sqrt(dx * dx + dy * dy);
    const rp = b.r[p] as number;
    if (!contactResolved(d, rp + (b.r[q] as number))) this.requireResolved(p, q, xp, yp, xq, yq);
    const approach = discDiscResponse(xp, yp, vxp, vyp, mp, xq, yq, vxq, vyq, mq, vel);
    this.setMotion(p, t, xp, yp, vel[0] as number, vel[1] as number);
    this.setMotion(q, t, xq, yq, vel[2] as number, vel[3] as number);
    const ev = this.ev;
    ev.time = t;
    ev.kind = "bodyBody";
    ev.a = b.ids[p] as string;
    ev.b = b.ids[q] as string;
    ev.nx = dx / d;
    ev.ny = dy / d;
    ev.px = xp + rp * ev.nx;
    ev.py = yp + rp * ev.ny;
    ev.impulse = impulseMagnitude(mp, mq, approach);
    this.tally.bodyBody++;
    this.predict(p);
    this.predict(q);
  }

  protected processStop(s: number): void {
    const b = this.store;
    const t = this.now;
    const x = this.xAt(s, t);
    const y = this.yAt(s, t);
    this.setMotion(s, t, x, y, 0, 0);
    const ev = this.ev;
    ev.time = t;
    ev.kind = "stop";
    ev.a = b.ids[s] as string;
    ev.b = null;
    ev.px = x;
    ev.py = y;
    ev.nx = 0;
    ev.ny = 0;
    ev.impulse = 0;
    this.tally.stop++;
    this.predict(s);
  }

  /** Process slot s's obstacle event now; `before` is the time before it, for the Zeno guard (after the refusal test). */
  protected processObstacle(s: number, kind: number, index: number, aux: number, before: number): void {
    const b = this.store;
    const t = this.now;
    const x = this.xAt(s, t);
    const y = this.yAt(s, t);
    const otherId = this.obstacleContact(s, kind, index, aux, x, y);
    const nx = contact[0] as number;
    const ny = contact[1] as number;
    // Inline rather than reflectOff: this is the hot path of wall-heavy scenes, and an extra call here
    // measured 3-5 % more cycles on Galperin (V8 inlines less into processObstacle).
    const approach = reflectResponse(this.vxAt(s, t), this.vyAt(s, t), nx, ny, vel);
    if (approach <= 0 && (b.mot[s * 8 + 5] as number) * nx + (b.mot[s * 8 + 6] as number) * ny > 0)
      this.reflectOff(s, otherId, nx, ny);
    this.guardZeno(before, s, kind);
    this.setMotion(s, t, x, y, vel[0] as number, vel[1] as number);
    const nn = Math.sqrt(nx * nx + ny * ny);
    const ev = this.ev;
    ev.time = t;
    ev.kind = kind === EV_LINE ? "bodyLine" : "bodyPoint";
    ev.a = b.ids[s] as string;
    ev.b = otherId;
    ev.px = contact[2] as number;
    ev.py = contact[3] as number;
    ev.nx = nx / nn;
    ev.ny = ny / nn;
    const m = b.m[s] as number;
    ev.impulse = m === INF ? (approach > 0 ? INF : 0) : 2 * m * approach;
    if (kind === EV_LINE) this.tally.bodyLine++;
    else this.tally.bodyPoint++;
    this.predict(s);
  }

  /**
   * Throws the SimulationError of a contact the doubles cannot place (physics/resolution.ts) when
   * bodies s and o, centred at (xs, ys) and (xo, yo), are not within it of touching; else nothing.
   */
  private requireResolved(s: number, o: number, xs: number, ys: number, xo: number, yo: number): void {
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
      what: `body '${ids[0]}' meets body '${ids[1]}'`,
      between: "the centres",
      t,
      d,
      D,
      coordinate: Math.max(Math.abs(xs), Math.abs(ys), Math.abs(xo), Math.abs(yo)),
      speed: Math.max(this.speedAt(s, t), this.speedAt(o, t)),
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
      what: `body '${who}' meets '${id}'`,
      between: line ? "the centre and the line" : "the centre and the point",
      t,
      d,
      D: r,
      coordinate: Math.max(Math.abs(x), Math.abs(y), Math.abs(px), Math.abs(py)),
      speed: this.speedAt(s, t),
    });
    throw new SimulationError(message, t, [who, id]);
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
  private obstacleContact(s: number, kind: number, index: number, aux: number, x: number, y: number): string {
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
  private reflectOff(s: number, otherId: string, nx: number, ny: number): number {
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
        `body '${this.store.ids[s]}' rests against '${otherId}' under an acceleration at t=${t}: resting contact is not supported (it would take infinitely many bounces)`,
        t,
        [this.store.ids[s] as string, otherId],
      );
    }
    return approach;
  }
}
