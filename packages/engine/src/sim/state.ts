/**
 * The state of the event-driven simulation: bodies (their current motions), obstacles, the grid,
 * the event heap, globals and counters; the motion and broad-phase helpers; and the canonical order
 * of simultaneous events. Prediction (predictor.ts) and processing (simulator.ts) build on it.
 *
 * Cell crossings never change a motion: the grid only decides which pairs are tested.
 */
import { type MotionLaw, motionLaw, positionAt, velocityAt } from "../physics/motion.js";
import { GRID_CELL_MARGIN, GRID_CELLS_PER_BODY, GRID_MIN_BODIES } from "../tolerances.js";
import { BodyStore, EV_BODY, EV_CROSS, EV_LINE, EV_POINT } from "./bodyStore.js";
import { CalendarQueue } from "./calendarQueue.js";
import { BIG_CELL, cellRadius, Grid } from "./grid.js";
import type { Line, Point } from "./obstacles.js";
import { rasterizeSegment } from "./rasterize.js";
import type { EventCounts, Optimizations, Vec2, WorldEvent } from "./types.js";
import { ZenoWatch } from "./zenoWatch.js";

const INF = Number.POSITIVE_INFINITY;
const law: MotionLaw = { ax: 0, ay: 0, tEnd: INF };

export class SimState {
  /** Current time, friction field g and gravity field (read through the getters below). */
  protected now: number;
  protected frictionG: number;
  protected gravX: number;
  protected gravY: number;
  readonly opt: Required<Optimizations>;
  protected store: BodyStore;
  protected grid: Grid;
  protected heap: CalendarQueue;
  protected lineList: Line[] = [];
  protected pointList: Point[] = [];
  /** Indices of infinite lines and rays (tested against every moving body). */
  protected globalLines: number[] = [];
  /** Per obstacle: the prediction stamp that last tested it (avoids testing it twice per prediction). */
  protected obstStamp: Int32Array = new Int32Array(0);
  protected stamp = 0;
  /**
   * Largest radius the grid's cells were built for. A larger body is a big body (at most
   * GRID_BIG_BODIES_MAX of them; more force a rebuild with larger cells).
   */
  protected gridMaxR = 0;
  /**
   * Slots of the big bodies: kept out of the cells (grid.cellOf = BIG_CELL), each tested against every
   * body and obstacle when predicted, and every body tests them, so that one disc of radius 100
   * among thousands of radius 1 does not make every cell 100 times too large.
   */
  protected bigBodies: number[] = [];
  /** Predictions of all bodies must be recomputed before the next event (grid rebuilt, obstacles or globals changed). */
  protected dirty = true;
  readonly counts: EventCounts = { bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0 };
  /** Reports runs of events the exact model cannot pass (zenoWatch.ts). */
  protected readonly zeno = new ZenoWatch();
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
    this.now = time;
    this.frictionG = g;
    this.gravX = gx;
    this.gravY = gy;
    this.opt = {
      broadPhase: opt.broadPhase ?? true,
      pathBounds: opt.pathBounds ?? true,
      quadraticFastPath: opt.quadraticFastPath ?? true,
      restingSkip: opt.restingSkip ?? true,
    };
    this.store = new BodyStore();
    this.grid = new Grid(this.store.capacity);
    this.heap = new CalendarQueue(this.store.capacity, (a, b) => this.tieLess(a, b));
  }

  /** The world's current time (read-only: `advance` and the edits move it). */
  get time(): number {
    return this.now;
  }

  /** The friction field g (read-only: change it with `setGlobal`). */
  get g(): number {
    return this.frictionG;
  }

  /** The gravity field's components (read-only: change them with `setGlobal`). */
  get gx(): number {
    return this.gravX;
  }

  get gy(): number {
    return this.gravY;
  }

  /** The gravity field as a pair (a fresh copy; change it with `setGlobal`). */
  get gravity(): Vec2 {
    return [this.gravX, this.gravY];
  }

  /** Copy all state into `target` (a fresh Simulator of the same class). */
  protected copyInto(target: SimState): void {
    target.now = this.now;
    target.frictionG = this.frictionG;
    target.gravX = this.gravX;
    target.gravY = this.gravY;
    target.store = this.store.clone();
    target.grid = this.grid.clone();
    target.heap = this.heap.cloneWith((a, b) => target.tieLess(a, b));
    target.lineList = this.lineList.slice();
    target.pointList = this.pointList.slice();
    target.gridMaxR = this.gridMaxR;
    target.bigBodies = this.bigBodies.slice();
    target.globalLines = this.globalLines;
    target.obstStamp = new Int32Array(this.obstStamp.length);
    target.dirty = this.dirty;
    Object.assign(target.counts, this.counts);
    target.zeno.load(this.zeno.save());
  }

  // ---- motion -------------------------------------------------------------------------------

  /** Start a new motion of body s at time t from (x, y) with velocity (vx, vy). */
  protected setMotion(s: number, t: number, x: number, y: number, vx: number, vy: number): void {
    const b = this.store;
    motionLaw(t, vx, vy, b.mu[s] as number, this.frictionG, this.gravX, this.gravY, law);
    b.mot[s * 8 + 0] = t;
    b.mot[s * 8 + 1] = x;
    b.mot[s * 8 + 2] = y;
    b.mot[s * 8 + 3] = vx;
    b.mot[s * 8 + 4] = vy;
    b.mot[s * 8 + 5] = law.ax;
    b.mot[s * 8 + 6] = law.ay;
    b.mot[s * 8 + 7] = law.tEnd;
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
    return positionAt(
      b.mot[s * 8 + 0] as number,
      b.mot[s * 8 + 1] as number,
      b.mot[s * 8 + 3] as number,
      b.mot[s * 8 + 5] as number,
      t,
    );
  }

  protected yAt(s: number, t: number): number {
    const b = this.store;
    return positionAt(
      b.mot[s * 8 + 0] as number,
      b.mot[s * 8 + 2] as number,
      b.mot[s * 8 + 4] as number,
      b.mot[s * 8 + 6] as number,
      t,
    );
  }

  /** Velocity of body s at time t (t within its current motion). */
  protected vxAt(s: number, t: number): number {
    const m = this.store.mot;
    return velocityAt(m[s * 8 + 0] as number, m[s * 8 + 3] as number, m[s * 8 + 5] as number, t);
  }

  protected vyAt(s: number, t: number): number {
    const m = this.store.mot;
    return velocityAt(m[s * 8 + 0] as number, m[s * 8 + 4] as number, m[s * 8 + 6] as number, t);
  }

  protected isMoving(s: number): boolean {
    const b = this.store;
    return (
      b.mot[s * 8 + 3] !== 0 || b.mot[s * 8 + 4] !== 0 || b.mot[s * 8 + 5] !== 0 || b.mot[s * 8 + 6] !== 0
    );
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
    const radii: number[] = extra ? [er] : [];
    let minX = extra ? ex : INF;
    let minY = extra ? ey : INF;
    let maxX = extra ? ex : -INF;
    let maxY = extra ? ey : -INF;
    let n = extra ? 1 : 0;
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      n++;
      const x = this.xAt(s, this.now);
      const y = this.yAt(s, this.now);
      radii.push(b.r[s] as number);
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
      let w = 2 * cellRadius(radii) * slack * GRID_CELL_MARGIN;
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
    this.bigBodies = [];
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      this.placeInGrid(s, this.xAt(s, this.now), this.yAt(s, this.now));
    }
    this.rasterizeObstacles();
    this.dirty = true;
  }

  /** Put body s (not in the grid yet), now at (x, y), in its cell, or among the big bodies. */
  protected placeInGrid(s: number, x: number, y: number): void {
    if ((this.store.r[s] as number) > this.gridMaxR) {
      this.grid.cellOf[s] = BIG_CELL;
      this.bigBodies.push(s);
    } else this.grid.insert(s, this.cellAt(x, y));
  }

  /** Take body s out of its cell or out of the big bodies. */
  protected takeFromGrid(s: number): void {
    if (this.grid.cellOf[s] === BIG_CELL) {
      this.bigBodies.splice(this.bigBodies.indexOf(s), 1);
      this.grid.cellOf[s] = -1;
    } else this.grid.remove(s);
  }

  protected cellAt(x: number, y: number): number {
    return this.grid.row(y) * this.grid.nx + this.grid.column(x);
  }

  /** Register segments and points in the grid cells they pass through; lines and rays stay global. */
  protected rasterizeObstacles(): void {
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

  // ---- canonical order of simultaneous events -----------------------------------------------

  protected rankOf(s: number): number {
    const b = this.store;
    return (b.crossTime[s] as number) <= (b.evTime[s] as number) ? EV_CROSS : (b.evKind[s] as number);
  }

  /** The two ids that name slot s's next event canonically: [first, second]. */
  protected eventIds(s: number, rank: number): [string, string] {
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
}
