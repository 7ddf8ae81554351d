/**
 * A deliberately simple reference simulator, for tests only: after every event it recomputes every
 * pair (the 2022 seed's method, O(n^2) per event), with no broad phase, no event queue, no caching.
 * It shares the pure kernels (motion, time of impact, response) with the World, so any difference
 * in the event sequence points at the World's scheduling machinery (grid, heap, invalidation). The
 * kernels' times are checked independently elsewhere: world.prop.test.ts measures the gap at every
 * collision from the states alone (a contact distance scaled by 1 + 1e-6 inside the time-of-impact
 * kernel passed this comparison and failed that check), and the kernels have their own exact tests.
 * The contact times it recomputes are referenceTimes.ts's; here, the search for the earliest event
 * (in the World's canonical order of simultaneous events) and its processing.
 */
import { motionLaw } from "../src/physics/motion.js";
import { discDiscResponse, reflectResponse } from "../src/physics/response.js";
import { type Line, makeLine } from "../src/sim/obstacles.js";
import type { EventKind, Vec2 } from "../src/sim/types.js";
import { type RefBody, refLineTime, refPairTime, refPointTime, refPos, refVelo } from "./referenceTimes.js";

export interface SceneSpec {
  g: number;
  gravity: Vec2;
  bodies: { id: string; x: number; y: number; vx: number; vy: number; r: number; m: number; mu: number }[];
  lines: { id: string; p1: Vec2; p2: Vec2; kind: "line" | "ray" | "segment" }[];
  points: { id: string; p: Vec2 }[];
}

export interface RefEvent {
  time: number;
  kind: EventKind;
  a: string;
  b: string | null;
}

const INF = Number.POSITIVE_INFINITY;
const RANK: Record<EventKind, number> = { stop: 2, bodyLine: 3, bodyPoint: 4, bodyBody: 5 };

interface Candidate {
  time: number;
  kind: EventKind;
  body: number;
  other: number;
  aux: number;
  ids: [string, string];
}

export class ReferenceWorld {
  time = 0;
  private bodies: RefBody[];
  private lines: Line[];
  private points: { id: string; x: number; y: number }[];
  private readonly spec: SceneSpec;

  constructor(spec: SceneSpec) {
    this.spec = spec;
    this.lines = spec.lines.map((l) => makeLine(l.id, l.p1, l.p2, l.kind));
    this.points = spec.points.map((p) => ({ id: p.id, x: p.p[0], y: p.p[1] }));
    this.bodies = spec.bodies.map((b) => {
      const body: RefBody = {
        id: b.id,
        t0: 0,
        x0: 0,
        y0: 0,
        vx: 0,
        vy: 0,
        ax: 0,
        ay: 0,
        tEnd: INF,
        r: b.r,
        m: b.m,
        mu: b.mu,
      };
      this.setMotion(body, 0, b.x, b.y, b.vx, b.vy);
      return body;
    });
  }

  private setMotion(b: RefBody, t: number, x: number, y: number, vx: number, vy: number): void {
    const law = motionLaw(t, vx, vy, b.mu, this.spec.g, this.spec.gravity[0], this.spec.gravity[1], {
      ax: 0,
      ay: 0,
      tEnd: INF,
    });
    Object.assign(b, { t0: t, x0: x, y0: y, vx, vy, ax: law.ax, ay: law.ay, tEnd: law.tEnd });
  }

  private static before(a: Candidate, b: Candidate): boolean {
    if (a.time !== b.time) return a.time < b.time;
    if (RANK[a.kind] !== RANK[b.kind]) return RANK[a.kind] < RANK[b.kind];
    if (a.ids[0] !== b.ids[0]) return a.ids[0] < b.ids[0];
    if (a.ids[1] !== b.ids[1]) return a.ids[1] < b.ids[1];
    return a.aux < b.aux;
  }

  /** The earliest event, by recomputing everything. */
  private next(): Candidate | null {
    let best: Candidate | null = null;
    const offer = (c: Candidate): void => {
      if (c.time !== INF && (best === null || ReferenceWorld.before(c, best))) best = c;
    };
    const bs = this.bodies;
    for (let i = 0; i < bs.length; i++) {
      const b = bs[i] as RefBody;
      if (b.tEnd < INF)
        offer({
          time: Math.max(this.time, b.tEnd),
          kind: "stop",
          body: i,
          other: -1,
          aux: 0,
          ids: [b.id, ""],
        });
      for (let j = i + 1; j < bs.length; j++) {
        const o = bs[j] as RefBody;
        const ids: [string, string] = b.id < o.id ? [b.id, o.id] : [o.id, b.id];
        offer({ time: refPairTime(b, o, this.time), kind: "bodyBody", body: i, other: j, aux: 0, ids });
      }
      this.lines.forEach((line, k) => {
        offer({
          time: refLineTime(b, line, this.time),
          kind: "bodyLine",
          body: i,
          other: k,
          aux: 0,
          ids: [b.id, line.id],
        });
        if (line.kind !== "line")
          offer({
            time: refPointTime(b, line.x1, line.y1, this.time),
            kind: "bodyLine",
            body: i,
            other: k,
            aux: 1,
            ids: [b.id, line.id],
          });
        if (line.kind === "segment")
          offer({
            time: refPointTime(b, line.x2, line.y2, this.time),
            kind: "bodyLine",
            body: i,
            other: k,
            aux: 2,
            ids: [b.id, line.id],
          });
      });
      this.points.forEach((p, k) => {
        offer({
          time: refPointTime(b, p.x, p.y, this.time),
          kind: "bodyPoint",
          body: i,
          other: k,
          aux: 0,
          ids: [b.id, p.id],
        });
      });
    }
    return best;
  }

  /** Process up to maxEvents events; returns them in order. */
  run(maxEvents: number): RefEvent[] {
    const log: RefEvent[] = [];
    const out = new Float64Array(4);
    while (log.length < maxEvents) {
      const c = this.next();
      if (c === null) break;
      const t = c.time;
      this.time = t;
      const b = this.bodies[c.body] as RefBody;
      const [x, y] = refPos(b, t);
      const [vx, vy] = refVelo(b, t);
      if (c.kind === "stop") {
        this.setMotion(b, t, x, y, 0, 0);
        log.push({ time: t, kind: "stop", a: b.id, b: null });
      } else if (c.kind === "bodyBody") {
        const o = this.bodies[c.other] as RefBody;
        const [p, q] = b.id < o.id ? [b, o] : [o, b];
        const [xp, yp] = refPos(p, t);
        const [xq, yq] = refPos(q, t);
        const [vxp, vyp] = refVelo(p, t);
        const [vxq, vyq] = refVelo(q, t);
        discDiscResponse(xp, yp, vxp, vyp, p.m, xq, yq, vxq, vyq, q.m, out);
        this.setMotion(p, t, xp, yp, out[0] as number, out[1] as number);
        this.setMotion(q, t, xq, yq, out[2] as number, out[3] as number);
        log.push({ time: t, kind: "bodyBody", a: p.id, b: q.id });
      } else {
        let nx: number;
        let ny: number;
        let id: string;
        if (c.kind === "bodyLine" && c.aux === 0) {
          const line = this.lines[c.other] as Line;
          const side = line.nx * (x - line.x1) + line.ny * (y - line.y1);
          nx = side > 0 ? line.ey : -line.ey;
          ny = side > 0 ? -line.ex : line.ex;
          id = line.id;
        } else if (c.kind === "bodyLine") {
          const line = this.lines[c.other] as Line;
          nx = (c.aux === 1 ? line.x1 : line.x2) - x;
          ny = (c.aux === 1 ? line.y1 : line.y2) - y;
          id = line.id;
        } else {
          const p = this.points[c.other] as { id: string; x: number; y: number };
          nx = p.x - x;
          ny = p.y - y;
          id = p.id;
        }
        reflectResponse(vx, vy, nx, ny, out);
        this.setMotion(b, t, x, y, out[0] as number, out[1] as number);
        log.push({ time: t, kind: c.kind, a: b.id, b: id });
      }
    }
    return log;
  }
}
