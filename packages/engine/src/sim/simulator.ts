/**
 * The event-driven core of the World: predicts each body's next event, keeps them in an indexed
 * heap, and processes them in time order.
 *
 * Invariants:
 * - Each body holds its earliest predicted interaction (collision or stop) and its next cell
 *   crossing; the heap key is the earlier of the two. After any change of a body's motion its
 *   predictions are recomputed; predictions of partners that involved it become stale (their
 *   recorded partner version no longer matches) and are recomputed when they reach the top.
 * - Every pair prediction is a pure function of the two motions (solved from the later of their
 *   start times), so it gives the same bits whenever and from whichever side it is computed. With
 *   the canonical order of simultaneous events this makes the simulation bit-identical whatever
 *   order bodies were added in.
 * - Cell crossings never change a motion: the grid only decides which pairs are tested.
 */
import { type MotionLaw, motionLaw, positionAt, velocityAt } from "../physics/motion.js";
import { discDiscResponse, impulseMagnitude, reflectResponse } from "../physics/response.js";
import { discDiscTime, discLineCrossings, firstDownCrossingQuadratic } from "../physics/timeOfImpact.js";
import {
  GRID_CELL_MARGIN,
  GRID_CELLS_PER_BODY,
  GRID_MIN_BODIES,
  SIMULTANEOUS_EVENTS_PER_BODY,
} from "../tolerances.js";
import { BodyStore, EV_BODY, EV_CROSS, EV_LINE, EV_NONE, EV_POINT, EV_STOP } from "./bodyStore.js";
import { SimulationError } from "./errors.js";
import { IndexedHeap } from "./eventQueue.js";
import { Grid } from "./grid.js";
import { type Line, lineParameter, type Point, parameterOnLine } from "./obstacles.js";
import { rasterizeSegment } from "./rasterize.js";
import type { EventCounts, Optimizations, WorldEvent } from "./types.js";

const INF = Number.POSITIVE_INFINITY;
const law: MotionLaw = { ax: 0, ay: 0, tEnd: INF };
const sides = new Float64Array(2);
const vel = new Float64Array(4);

function idLess(a: string, b: string): boolean {
  return a < b;
}

export class Simulator {
  time: number;
  g: number;
  gx: number;
  gy: number;
  readonly opt: Required<Optimizations>;
  protected store: BodyStore;
  protected grid: Grid;
  protected heap: IndexedHeap;
  protected lineList: Line[] = [];
  protected pointList: Point[] = [];
  /** Indices of infinite lines and rays (tested against every moving body). */
  private globalLines: number[] = [];
  /** Per obstacle: the prediction stamp that last tested it (avoids testing it twice per prediction). */
  private obstStamp = new Int32Array(0);
  private stamp = 0;
  /** Largest radius the grid was built for; a larger body forces a rebuild. */
  protected gridMaxR = 0;
  /** Predictions of all bodies must be recomputed before the next event (grid rebuilt, obstacles or globals changed). */
  protected dirty = true;
  readonly counts: EventCounts = { bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0 };
  private sameTime = -INF;
  private sameTimeCount = 0;
  protected readonly ev: WorldEvent = {
    time: 0,
    kind: "stop",
    a: "",
    b: null,
    px: 0,
    py: 0,
    nx: 0,
    ny: 0,
    impulse: 0,
  };

  constructor(time: number, g: number, gx: number, gy: number, opt: Optimizations) {
    this.time = time;
    this.g = g;
    this.gx = gx;
    this.gy = gy;
    this.opt = {
      broadPhase: opt.broadPhase ?? true,
      pathBounds: opt.pathBounds ?? true,
      quadraticFastPath: opt.quadraticFastPath ?? true,
      restingSkip: opt.restingSkip ?? true,
    };
    this.store = new BodyStore();
    this.grid = new Grid(this.store.capacity);
    this.heap = new IndexedHeap(this.store.capacity, (a, b) => this.tieLess(a, b));
  }

  /** Copy all state into `target` (a fresh Simulator of the same class). */
  protected copyInto(target: Simulator): void {
    target.time = this.time;
    target.g = this.g;
    target.gx = this.gx;
    target.gy = this.gy;
    target.store = this.store.clone();
    target.grid = this.grid.clone();
    target.heap = this.heap.cloneWith((a, b) => target.tieLess(a, b));
    target.lineList = this.lineList.slice();
    target.pointList = this.pointList.slice();
    target.gridMaxR = this.gridMaxR;
    target.globalLines = this.globalLines;
    target.obstStamp = new Int32Array(this.obstStamp.length);
    target.dirty = this.dirty;
    Object.assign(target.counts, this.counts);
    target.sameTime = this.sameTime;
    target.sameTimeCount = this.sameTimeCount;
  }

  // ---- motion -------------------------------------------------------------------------------

  /** Start a new motion of body s at time t from (x, y) with velocity (vx, vy). */
  protected setMotion(s: number, t: number, x: number, y: number, vx: number, vy: number): void {
    const b = this.store;
    motionLaw(t, vx, vy, b.mu[s] as number, this.g, this.gx, this.gy, law);
    b.t0[s] = t;
    b.x0[s] = x;
    b.y0[s] = y;
    b.vx0[s] = vx;
    b.vy0[s] = vy;
    b.ax[s] = law.ax;
    b.ay[s] = law.ay;
    b.tEnd[s] = law.tEnd;
    b.version[s] = (b.version[s] as number) + 1;
    const r = b.r[s] as number;
    const still = vx === 0 && vy === 0 && law.ax === 0 && law.ay === 0;
    if (still || law.tEnd < INF) {
      const xe = still ? x : positionAt(t, x, vx, law.ax, law.tEnd);
      const ye = still ? y : positionAt(t, y, vy, law.ay, law.tEnd);
      b.boxMinX[s] = Math.min(x, xe) - r;
      b.boxMaxX[s] = Math.max(x, xe) + r;
      b.boxMinY[s] = Math.min(y, ye) - r;
      b.boxMaxY[s] = Math.max(y, ye) + r;
    } else {
      b.boxMinX[s] = -INF;
      b.boxMinY[s] = -INF;
      b.boxMaxX[s] = INF;
      b.boxMaxY[s] = INF;
    }
  }

  /** Position of body s at time t (t within its current motion). */
  protected xAt(s: number, t: number): number {
    const b = this.store;
    return positionAt(b.t0[s] as number, b.x0[s] as number, b.vx0[s] as number, b.ax[s] as number, t);
  }

  protected yAt(s: number, t: number): number {
    const b = this.store;
    return positionAt(b.t0[s] as number, b.y0[s] as number, b.vy0[s] as number, b.ay[s] as number, t);
  }

  protected isMoving(s: number): boolean {
    const b = this.store;
    return b.vx0[s] !== 0 || b.vy0[s] !== 0 || b.ax[s] !== 0 || b.ay[s] !== 0;
  }

  // ---- broad phase --------------------------------------------------------------------------

  /**
   * Rebuild the grid around the current positions (never changes a motion). A disc (ex, ey, er)
   * about to be added is included; while editing (`slack` > 1) the grid is made roomier so that
   * a stream of additions rebuilds it only O(log n) times; `advance` rebuilds it tight.
   */
  protected rebuildGrid(ex = Number.NaN, ey = Number.NaN, er = 0, slack = 1): void {
    const b = this.store;
    const extra = !Number.isNaN(ex);
    let maxR = er * slack;
    let minX = extra ? ex : INF;
    let minY = extra ? ey : INF;
    let maxX = extra ? ex : -INF;
    let maxY = extra ? ey : -INF;
    let n = extra ? 1 : 0;
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      n++;
      const x = this.xAt(s, this.time);
      const y = this.yAt(s, this.time);
      maxR = Math.max(maxR, (b.r[s] as number) * slack);
      minX = Math.min(minX, x);
      maxX = Math.max(maxX, x);
      minY = Math.min(minY, y);
      maxY = Math.max(maxY, y);
    }
    this.grid.reserve(b.capacity);
    this.heap.reserve(b.capacity);
    if (n < GRID_MIN_BODIES || !this.opt.broadPhase) {
      this.grid.reset(0, 0, 1, 1, 1);
      this.gridMaxR = INF;
    } else {
      let w = 2 * maxR * GRID_CELL_MARGIN;
      // Leave room around the bodies so that edits nearby do not force a rebuild.
      const padX = slack > 1 ? Math.max(0.5 * slack * (maxX - minX), 2 * w) : 2 * w;
      const padY = slack > 1 ? Math.max(0.5 * slack * (maxY - minY), 2 * w) : 2 * w;
      const width = maxX - minX + 2 * padX;
      const height = maxY - minY + 2 * padY;
      const maxCells = Math.max(16, GRID_CELLS_PER_BODY * n);
      if ((width / w) * (height / w) > maxCells) w = Math.sqrt((width * height) / maxCells);
      const nx = Math.max(1, Math.min(maxCells, Math.ceil(width / w)));
      const ny = Math.max(1, Math.min(maxCells, Math.ceil(height / w)));
      this.grid.reset(minX - padX, minY - padY, w, nx, ny);
      this.gridMaxR = w / (2 * GRID_CELL_MARGIN);
    }
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      this.grid.insert(s, this.cellAt(this.xAt(s, this.time), this.yAt(s, this.time)));
    }
    this.rasterizeObstacles();
    this.dirty = true;
  }

  protected cellAt(x: number, y: number): number {
    return this.grid.row(y) * this.grid.nx + this.grid.column(x);
  }

  /** Recompute every body's predictions (after a rebuild or a change of obstacles or globals). */
  protected predictAll(): void {
    const b = this.store;
    for (let s = 0; s < b.slotCount; s++) if (b.ids[s] !== undefined) this.predict(s);
    this.dirty = false;
  }

  // ---- prediction ---------------------------------------------------------------------------

  /** Earliest contact time of bodies s and o, or +Infinity. */
  protected pairTime(s: number, o: number): number {
    const b = this.store;
    if (this.opt.pathBounds) {
      if (
        (b.boxMinX[s] as number) > (b.boxMaxX[o] as number) ||
        (b.boxMinX[o] as number) > (b.boxMaxX[s] as number) ||
        (b.boxMinY[s] as number) > (b.boxMaxY[o] as number) ||
        (b.boxMinY[o] as number) > (b.boxMaxY[s] as number)
      )
        return INF;
    }
    const ts = b.t0[s] as number;
    const to = b.t0[o] as number;
    const tb = Math.max(ts, to);
    const hi = Math.min(b.tEnd[s] as number, b.tEnd[o] as number) - tb;
    const axs = b.ax[s] as number;
    const ays = b.ay[s] as number;
    const axo = b.ax[o] as number;
    const ayo = b.ay[o] as number;
    const dx =
      positionAt(to, b.x0[o] as number, b.vx0[o] as number, axo, tb) -
      positionAt(ts, b.x0[s] as number, b.vx0[s] as number, axs, tb);
    const dy =
      positionAt(to, b.y0[o] as number, b.vy0[o] as number, ayo, tb) -
      positionAt(ts, b.y0[s] as number, b.vy0[s] as number, ays, tb);
    const ux = velocityAt(to, b.vx0[o] as number, axo, tb) - velocityAt(ts, b.vx0[s] as number, axs, tb);
    const uy = velocityAt(to, b.vy0[o] as number, ayo, tb) - velocityAt(ts, b.vy0[s] as number, ays, tb);
    // Cheap rejection before any solve: with no relative acceleration a receding pair never meets.
    if (axo === axs && ayo === ays && dx * ux + dy * uy >= 0 && this.opt.quadraticFastPath) return INF;
    const R = (b.r[s] as number) + (b.r[o] as number);
    const tau = discDiscTime(
      dx,
      dy,
      ux,
      uy,
      axo - axs,
      ayo - ays,
      R,
      this.time - tb,
      hi,
      this.opt.quadraticFastPath,
    );
    if (tau === INF) return INF;
    const t = tb + tau;
    return Math.max(t, this.time);
  }

  /** Earliest contact of body s with a point at (px, py), or +Infinity. */
  protected pointTime(s: number, px: number, py: number): number {
    const b = this.store;
    const t0 = b.t0[s] as number;
    const tau = discDiscTime(
      (b.x0[s] as number) - px,
      (b.y0[s] as number) - py,
      b.vx0[s] as number,
      b.vy0[s] as number,
      b.ax[s] as number,
      b.ay[s] as number,
      b.r[s] as number,
      this.time - t0,
      (b.tEnd[s] as number) - t0,
      this.opt.quadraticFastPath,
    );
    if (tau === INF) return INF;
    const t = t0 + tau;
    return Math.max(t, this.time);
  }

  /**
   * Earliest contact of body s with the line (its interior for rays and segments; their end points
   * are tested as points). Returns the time, or +Infinity.
   */
  protected lineTime(s: number, line: Line): number {
    const b = this.store;
    const t0 = b.t0[s] as number;
    const lo = this.time - t0;
    const hi = (b.tEnd[s] as number) - t0;
    const x0 = b.x0[s] as number;
    const y0 = b.y0[s] as number;
    const vx = b.vx0[s] as number;
    const vy = b.vy0[s] as number;
    const ax = b.ax[s] as number;
    const ay = b.ay[s] as number;
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
        const lambda = lineParameter(
          line,
          x0 + tau * (vx + 0.5 * ax * tau),
          y0 + tau * (vy + 0.5 * ay * tau),
        );
        if (!parameterOnLine(line.kind, lambda)) continue;
      }
      best = tau;
    }
    if (best === INF) return INF;
    const t = t0 + best;
    return Math.max(t, this.time);
  }

  /** Whether candidate (kind k1, other o1) comes before (k2, o2) for body s at the same time. */
  private candidateLess(k1: number, o1: number, a1: number, k2: number, o2: number, a2: number): boolean {
    if (k1 !== k2) return k1 < k2;
    if (k1 === EV_BODY) return idLess(this.store.ids[o1] as string, this.store.ids[o2] as string);
    if (k1 === EV_LINE) {
      const i1 = (this.lineList[o1] as Line).id;
      const i2 = (this.lineList[o2] as Line).id;
      return i1 !== i2 ? idLess(i1, i2) : a1 < a2;
    }
    if (k1 === EV_POINT) return idLess((this.pointList[o1] as Point).id, (this.pointList[o2] as Point).id);
    return false;
  }

  /** Offer a candidate event to body s; it is kept if earlier (or canonically first at the same time). */
  private offer(s: number, t: number, kind: number, other: number, aux: number): void {
    const b = this.store;
    const cur = b.evTime[s] as number;
    if (t > cur) return;
    if (
      t === cur &&
      !this.candidateLess(
        kind,
        other,
        aux,
        b.evKind[s] as number,
        b.evOther[s] as number,
        b.evAux[s] as number,
      )
    )
      return;
    b.evTime[s] = t;
    b.evKind[s] = kind;
    b.evOther[s] = other;
    b.evAux[s] = aux;
    b.evOtherVersion[s] = kind === EV_BODY ? (b.version[other] as number) : 0;
  }

  /** Test body s against the bodies in one grid cell. */
  private scanCell(s: number, cell: number, moving: boolean): void {
    const grid = this.grid;
    for (let o = grid.head[cell] as number; o >= 0; o = grid.next[o] as number) {
      if (o === s) continue;
      if (!moving && this.opt.restingSkip && !this.isMoving(o)) continue;
      const t = this.pairTime(s, o);
      if (t !== INF) this.offer(s, t, EV_BODY, o, 0);
    }
  }

  /** Recompute everything body s can run into next, and its next cell crossing. */
  protected predict(s: number): void {
    const b = this.store;
    const moving = this.isMoving(s);
    b.evTime[s] = INF;
    b.evKind[s] = EV_NONE;
    const tEnd = b.tEnd[s] as number;
    if (tEnd < INF) this.offer(s, Math.max(tEnd, this.time), EV_STOP, -1, 0);
    const grid = this.grid;
    const cell = grid.cellOf[s] as number;
    const cx = cell % grid.nx;
    const cy = (cell - cx) / grid.nx;
    this.stamp++;
    for (let y = cy - 1; y <= cy + 1; y++) {
      if (y < 0 || y >= grid.ny) continue;
      for (let x = cx - 1; x <= cx + 1; x++) {
        if (x < 0 || x >= grid.nx) continue;
        this.scanCell(s, y * grid.nx + x, moving);
        if (moving) this.scanCellObstacles(s, y * grid.nx + x);
      }
    }
    if (moving) for (const i of this.globalLines) this.testLine(s, i);
    b.crossTime[s] = moving ? this.crossing(s, cx, cy) : INF;
    const key = Math.min(b.evTime[s] as number, b.crossTime[s] as number);
    this.heap.set(s, key);
  }

  /** Test body s against line i: its interior, and the end points of rays and segments. */
  private testLine(s: number, i: number): void {
    const line = this.lineList[i] as Line;
    const t = this.lineTime(s, line);
    if (t !== INF) this.offer(s, t, EV_LINE, i, 0);
    if (line.kind !== "line") {
      const t1 = this.pointTime(s, line.x1, line.y1);
      if (t1 !== INF) this.offer(s, t1, EV_LINE, i, 1);
      if (line.kind === "segment") {
        const t2 = this.pointTime(s, line.x2, line.y2);
        if (t2 !== INF) this.offer(s, t2, EV_LINE, i, 2);
      }
    }
  }

  /** Test body s against the segments and points registered in one cell (each once per stamp). */
  private scanCellObstacles(s: number, cell: number): void {
    const grid = this.grid;
    const end = grid.obstStart[cell + 1] as number;
    for (let k = grid.obstStart[cell] as number; k < end; k++) {
      const code = grid.obstList[k] as number;
      const key = code >= 0 ? code : this.lineList.length - code - 1;
      if (this.obstStamp[key] === this.stamp) continue;
      this.obstStamp[key] = this.stamp;
      if (code >= 0) this.testLine(s, code);
      else {
        const p = this.pointList[-code - 1] as Point;
        const t = this.pointTime(s, p.x, p.y);
        if (t !== INF) this.offer(s, t, EV_POINT, -code - 1, 0);
      }
    }
  }

  /** Register segments and points in the grid cells they pass through; lines and rays stay global. */
  private rasterizeObstacles(): void {
    const pairs: number[] = [];
    const global: number[] = [];
    this.lineList.forEach((line, i) => {
      if (line.kind === "segment") rasterizeSegment(this.grid, line.x1, line.y1, line.x2, line.y2, i, pairs);
      else global.push(i);
    });
    this.pointList.forEach((p, i) => {
      rasterizeSegment(this.grid, p.x, p.y, p.x, p.y, -(i + 1), pairs);
    });
    this.grid.setObstacles(pairs);
    this.globalLines = global;
    this.obstStamp = new Int32Array(this.lineList.length + this.pointList.length);
    this.stamp = 0;
  }

  /** Time at which body s (in cell cx, cy) next leaves its cell; direction stored in crossDir. */
  private crossing(s: number, cx: number, cy: number): number {
    const b = this.store;
    const grid = this.grid;
    const t0 = b.t0[s] as number;
    const lo = this.time - t0;
    const hi = (b.tEnd[s] as number) - t0;
    const x0 = b.x0[s] as number;
    const y0 = b.y0[s] as number;
    const vx = b.vx0[s] as number;
    const vy = b.vy0[s] as number;
    const hax = 0.5 * (b.ax[s] as number);
    const hay = 0.5 * (b.ay[s] as number);
    let best = INF;
    let dir = -1;
    if (hax === 0 && hay === 0) {
      // Uniform motion (the common case): only the boundaries ahead can be crossed.
      if (vx > 0 && cx < grid.nx - 1) {
        best = Math.max(lo, (grid.boundaryX(cx + 1) - x0) / vx);
        dir = 1;
      } else if (vx < 0 && cx > 0) {
        best = Math.max(lo, (grid.boundaryX(cx) - x0) / vx);
        dir = 0;
      }
      if (vy > 0 && cy < grid.ny - 1) {
        const t = Math.max(lo, (grid.boundaryY(cy + 1) - y0) / vy);
        if (t < best) {
          best = t;
          dir = 3;
        }
      } else if (vy < 0 && cy > 0) {
        const t = Math.max(lo, (grid.boundaryY(cy) - y0) / vy);
        if (t < best) {
          best = t;
          dir = 2;
        }
      }
      b.crossDir[s] = dir;
      return best === INF ? INF : Math.max(this.time, t0 + best);
    }
    if (cx > 0) {
      const t = firstDownCrossingQuadratic(x0 - grid.boundaryX(cx), vx, hax, lo, hi);
      if (t < best) {
        best = t;
        dir = 0;
      }
    }
    if (cx < grid.nx - 1) {
      const t = firstDownCrossingQuadratic(grid.boundaryX(cx + 1) - x0, -vx, -hax, lo, hi);
      if (t < best) {
        best = t;
        dir = 1;
      }
    }
    if (cy > 0) {
      const t = firstDownCrossingQuadratic(y0 - grid.boundaryY(cy), vy, hay, lo, hi);
      if (t < best) {
        best = t;
        dir = 2;
      }
    }
    if (cy < grid.ny - 1) {
      const t = firstDownCrossingQuadratic(grid.boundaryY(cy + 1) - y0, -vy, -hay, lo, hi);
      if (t < best) {
        best = t;
        dir = 3;
      }
    }
    b.crossDir[s] = dir;
    if (best === INF) return INF;
    const t = t0 + best;
    return Math.max(t, this.time);
  }

  // ---- canonical order of simultaneous events -----------------------------------------------

  private rankOf(s: number): number {
    const b = this.store;
    return (b.crossTime[s] as number) <= (b.evTime[s] as number) ? EV_CROSS : (b.evKind[s] as number);
  }

  /** The two ids that name slot s's next event canonically: [first, second]. */
  private eventIds(s: number, rank: number): [string, string] {
    const b = this.store;
    const id = b.ids[s] as string;
    if (rank === EV_BODY) {
      const other = b.ids[b.evOther[s] as number] as string;
      return id < other ? [id, other] : [other, id];
    }
    if (rank === EV_LINE) return [id, (this.lineList[b.evOther[s] as number] as Line).id];
    if (rank === EV_POINT) return [id, (this.pointList[b.evOther[s] as number] as Point).id];
    return [id, ""];
  }

  /** Heap tie-break for two slots whose next events are at exactly the same time. */
  protected tieLess(a: number, c: number): boolean {
    const ra = this.rankOf(a);
    const rc = this.rankOf(c);
    if (ra !== rc) return ra < rc;
    const [a1, a2] = this.eventIds(a, ra);
    const [c1, c2] = this.eventIds(c, rc);
    if (a1 !== c1) return a1 < c1;
    if (a2 !== c2) return a2 < c2;
    return (this.store.evAux[a] as number) < (this.store.evAux[c] as number);
  }

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
    if (t > this.time) this.time = t;
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
    this.guardZeno();
    if (kind === EV_BODY) this.processBodyBody(s, b.evOther[s] as number);
    else if (kind === EV_STOP) this.processStop(s);
    else this.processObstacle(s, kind, b.evOther[s] as number, b.evAux[s] as number);
    onEvent?.(this.ev);
    return 1;
  }

  private guardZeno(): void {
    if (this.time !== this.sameTime) {
      this.sameTime = this.time;
      this.sameTimeCount = 0;
      return;
    }
    this.sameTimeCount++;
    if (this.sameTimeCount > SIMULTANEOUS_EVENTS_PER_BODY * Math.max(1, this.store.slotCount)) {
      throw new SimulationError(
        `more than ${this.sameTimeCount} events at the same instant t=${this.time}: a Zeno state (resting contact or an inelastic collapse) that the exact model cannot resolve`,
        this.time,
      );
    }
  }

  private processCrossing(s: number): void {
    const b = this.store;
    const grid = this.grid;
    const cell = grid.cellOf[s] as number;
    let cx = cell % grid.nx;
    let cy = (cell - cx) / grid.nx;
    const dir = b.crossDir[s] as number;
    if (dir === 0) cx--;
    else if (dir === 1) cx++;
    else if (dir === 2) cy--;
    else cy++;
    grid.move(s, cy * grid.nx + cx);
    // Only the row or column that just became adjacent holds new partners.
    this.stamp++;
    if (dir <= 1) {
      const x = dir === 0 ? cx - 1 : cx + 1;
      if (x >= 0 && x < grid.nx)
        for (let y = cy - 1; y <= cy + 1; y++)
          if (y >= 0 && y < grid.ny) this.scanNewCell(s, y * grid.nx + x);
    } else {
      const y = dir === 2 ? cy - 1 : cy + 1;
      if (y >= 0 && y < grid.ny)
        for (let x = cx - 1; x <= cx + 1; x++)
          if (x >= 0 && x < grid.nx) this.scanNewCell(s, y * grid.nx + x);
    }
    b.crossTime[s] = this.crossing(s, cx, cy);
    this.heap.set(s, Math.min(b.evTime[s] as number, b.crossTime[s] as number));
  }

  private scanNewCell(s: number, cell: number): void {
    this.scanCell(s, cell, true);
    this.scanCellObstacles(s, cell);
  }

  private processBodyBody(s: number, o: number): void {
    const b = this.store;
    // Canonical order: `a` is the body with the smaller id, so the arithmetic is the same whichever body held the event.
    const [p, q] = (b.ids[s] as string) < (b.ids[o] as string) ? [s, o] : [o, s];
    const t = this.time;
    const xp = this.xAt(p, t);
    const yp = this.yAt(p, t);
    const xq = this.xAt(q, t);
    const yq = this.yAt(q, t);
    const vxp = velocityAt(b.t0[p] as number, b.vx0[p] as number, b.ax[p] as number, t);
    const vyp = velocityAt(b.t0[p] as number, b.vy0[p] as number, b.ay[p] as number, t);
    const vxq = velocityAt(b.t0[q] as number, b.vx0[q] as number, b.ax[q] as number, t);
    const vyq = velocityAt(b.t0[q] as number, b.vy0[q] as number, b.ay[q] as number, t);
    const mp = b.m[p] as number;
    const mq = b.m[q] as number;
    const approach = discDiscResponse(xp, yp, vxp, vyp, mp, xq, yq, vxq, vyq, mq, vel);
    this.setMotion(p, t, xp, yp, vel[0] as number, vel[1] as number);
    this.setMotion(q, t, xq, yq, vel[2] as number, vel[3] as number);
    const dx = xq - xp;
    const dy = yq - yp;
    const d = Math.sqrt(dx * dx + dy * dy);
    const rp = b.r[p] as number;
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
    this.counts.bodyBody++;
    this.predict(p);
    this.predict(q);
  }

  private processStop(s: number): void {
    const b = this.store;
    const t = this.time;
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
    this.counts.stop++;
    this.predict(s);
  }

  private processObstacle(s: number, kind: number, index: number, aux: number): void {
    const b = this.store;
    const t = this.time;
    const x = this.xAt(s, t);
    const y = this.yAt(s, t);
    const vx = velocityAt(b.t0[s] as number, b.vx0[s] as number, b.ax[s] as number, t);
    const vy = velocityAt(b.t0[s] as number, b.vy0[s] as number, b.ay[s] as number, t);
    let cx: number;
    let cy: number;
    let nx: number;
    let ny: number;
    let otherId: string;
    if (kind === EV_LINE && aux === 0) {
      const line = this.lineList[index] as Line;
      otherId = line.id;
      // Unnormalised normal (-ey, ex), oriented from the disc towards the line.
      const side = line.nx * (x - line.x1) + line.ny * (y - line.y1);
      nx = side > 0 ? line.ey : -line.ey;
      ny = side > 0 ? -line.ex : line.ex;
      const len = Math.sqrt(line.ee);
      const r = b.r[s] as number;
      cx = x + (r * nx) / len;
      cy = y + (r * ny) / len;
    } else {
      let px: number;
      let py: number;
      if (kind === EV_LINE) {
        const line = this.lineList[index] as Line;
        otherId = line.id;
        px = aux === 1 ? line.x1 : line.x2;
        py = aux === 1 ? line.y1 : line.y2;
      } else {
        const point = this.pointList[index] as Point;
        otherId = point.id;
        px = point.x;
        py = point.y;
      }
      nx = px - x;
      ny = py - y;
      cx = px;
      cy = py;
    }
    const approach = reflectResponse(vx, vy, nx, ny, vel);
    if (approach <= 0 && (b.ax[s] as number) * nx + (b.ay[s] as number) * ny > 0) {
      throw new SimulationError(
        `body '${b.ids[s]}' rests against '${otherId}' under an acceleration at t=${t}: resting contact is not supported (it would take infinitely many bounces)`,
        t,
      );
    }
    this.setMotion(s, t, x, y, vel[0] as number, vel[1] as number);
    const nn = Math.sqrt(nx * nx + ny * ny);
    const ev = this.ev;
    ev.time = t;
    ev.kind = kind === EV_LINE ? "bodyLine" : "bodyPoint";
    ev.a = b.ids[s] as string;
    ev.b = otherId;
    ev.px = cx;
    ev.py = cy;
    ev.nx = nx / nn;
    ev.ny = ny / nn;
    const m = b.m[s] as number;
    ev.impulse = m === INF ? (approach > 0 ? INF : 0) : 2 * m * approach;
    if (kind === EV_LINE) this.counts.bodyLine++;
    else this.counts.bodyPoint++;
    this.predict(s);
  }
}
