/**
 * The state of the event-driven simulation: bodies (their current motions), obstacles, the grid,
 * the event heap, globals and counters; and the motion helpers. The canonical order of simultaneous
 * events, the heap's tie-break, is eventOrder.ts's. The broad phase (broadPhase.ts), prediction
 * (predictor.ts) and processing (simulator.ts) build on it.
 *
 * Cell crossings never change a motion: the grid only decides which pairs are tested.
 */
import { type MotionLaw, motionLaw, positionAt, velocityAt } from "../physics/motion.js";
import { BodyStore } from "./bodyStore.js";
import { CalendarQueue } from "./calendarQueue.js";
import { eventTieLess } from "./eventOrder.js";
import { Grid } from "./grid.js";
import { ObstacleIndex } from "./obstacleIndex.js";
import type { Line, Point } from "./obstacles.js";
import type { EventCounts, Optimizations, Vec2, WorldEventRecord } from "./types.js";
import { ZenoWatch } from "./zenoWatch.js";

const INF = Number.POSITIVE_INFINITY;
const law: MotionLaw = { ax: 0, ay: 0, tEnd: INF };
/**
 * The doubles of a new motion (t, x, y, vx, vy) on their way into setMotion's body: a double passed
 * to a call V8 does not inline is boxed, a heap allocation each (ten per collision otherwise).
 */
const MOTION_ARGS = new Float64Array(5);

/**
 * `counts` read-only: a frozen object with one enumerable getter per key, in its order, so a write
 * throws a TypeError (in strict code, as every ES module is; sloppy code's write changes nothing)
 * while reads, spreads, JSON and structuredClone (postMessage) see plain numbers; Node's
 * console.log shows the numbers too, not `[Getter]`.
 */
function readOnlyView(counts: EventCounts): Readonly<EventCounts> {
  const view: Record<string | symbol, unknown> = {};
  for (const key of Object.keys(counts) as (keyof EventCounts)[])
    Object.defineProperty(view, key, { enumerable: true, get: () => counts[key] });
  Object.defineProperty(view, Symbol.for("nodejs.util.inspect.custom"), { value: () => ({ ...counts }) });
  return Object.freeze(view) as unknown as Readonly<EventCounts>;
}

export class SimState {
  /**
   * Current time, friction field g and gravity field (read through the getters below). Given a
   * number here, not only in the constructor: a field declared without a value starts as
   * undefined, and V8 then keeps it as a tagged value, so that every new time stored a freshly
   * allocated heap number, with a write barrier (4.7 times per collision in a gas).
   */
  protected now = 0;
  protected frictionG = 0;
  protected gravX = 0;
  protected gravY = 0;
  /**
   * The optimisation switches in effect: WorldOptions.optimizations with the defaults (all true)
   * filled in. `declare`d like the fields below: a field definition would start it as undefined, and
   * V8 would check the object's map again after each load of it (solvePair reads it per pair test).
   * The pair test compares its switches with `=== true`: V8 does not know that a field holds a
   * boolean, and a plain test of one is a full ToBoolean (false, "", numbers, BigInts).
   */
  declare readonly opt: { [K in keyof Optimizations]-?: boolean };
  // `declare`: set in the constructor, never undefined, so V8 knows their classes (bodyStore.ts).
  declare protected store: BodyStore;
  declare protected grid: Grid;
  declare protected heap: CalendarQueue;
  /**
   * The lines and points, in the order they were added, and where each id sits in them
   * (obstacleIndex.ts). A removed one stays in its list until compactObstacles: every read of a
   * whole list compacts first (grid rebuilds, placement checks, copies); the simulation reads them
   * only after a rebuild, or after an edit that compacted them at once and renumbered what refers
   * to their positions (obstacleUpkeep.ts).
   */
  protected lineList: Line[] = [];
  protected pointList: Point[] = [];
  protected readonly lineAt = new ObstacleIndex<Line>();
  protected readonly pointAt = new ObstacleIndex<Point>();
  /** Indices of infinite lines and rays (tested against every moving body). */
  protected globalLines: number[] = [];
  /** Per obstacle: the prediction stamp that last tested it (avoids testing it twice per prediction). */
  protected obstStamp: Int32Array = new Int32Array(0);
  protected stamp = 0;
  /** Predictions of all bodies must be recomputed before the next event (grid rebuilt, obstacles or globals changed). */
  protected dirty = true;
  /** Bodies the grid's cells were sized for at its last rebuild (a disc about to be added included). */
  protected gridBodies = 0;
  /**
   * Counts the changes that can move the next event: a new motion (an event or an edit), a body
   * removed, an edit that leaves the predictions out of date (markDirty). Caches of the next event
   * time (World's query range) compare it; a cell crossing or a grid rebuild does not count.
   */
  protected changes = 0;

  /** The predictions are out of date (a global or an infinite line edited, ...): the next advance redoes them. */
  protected markDirty(): void {
    this.dirty = true;
    this.changes++;
  }
  /** The counts the World updates (`counts` shows them read-only). */
  protected readonly tally: EventCounts = { bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0 };
  private readonly tallyView = readOnlyView(this.tally);
  /**
   * Collisions by kind and friction stops processed by this World so far (a clone starts from a
   * copy). A live object, updated as events are processed: copy it to keep a snapshot. Read-only
   * in its type and at run time (a program that wrote into it changed what the World reported:
   * audit of session 20, review of session 29).
   */
  get counts(): Readonly<EventCounts> {
    return this.tallyView;
  }
  /** Reports runs of events the exact model cannot pass (zenoWatch.ts). */
  protected readonly zeno = new ZenoWatch();
  protected readonly ev: WorldEventRecord = {
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
    // frozen: `opt` is a public read, and a write from JavaScript switched an optimisation mid-run
    this.opt = Object.freeze({
      broadPhase: opt.broadPhase ?? true,
      pathBounds: opt.pathBounds ?? true,
      quadraticFastPath: opt.quadraticFastPath ?? true,
      restingSkip: opt.restingSkip ?? true,
      recedingReject: opt.recedingReject ?? true,
    });
    this.store = new BodyStore();
    this.grid = new Grid(this.store.capacity);
    this.heap = new CalendarQueue(this.store.capacity, this);
  }

  /**
   * The world's current time, on its absolute clock: events before it have been processed, and
   * edits happen at it (read-only: only `advance` moves it; edits do not).
   */
  get time(): number {
    return this.now;
  }

  /** The friction field g (read-only: change it with `setGlobal`). */
  get g(): number {
    return this.frictionG;
  }

  /** The gravity field's x component (read-only: change it with `setGlobal`). */
  get gx(): number {
    return this.gravX;
  }

  /** The gravity field's y component (read-only: change it with `setGlobal`). */
  get gy(): number {
    return this.gravY;
  }

  /** The gravity field as a pair (a fresh copy; change it with `setGlobal`). */
  get gravity(): Vec2 {
    return [this.gravX, this.gravY];
  }

  /** Drop removed lines and points from their lists (obstacleIndex.ts); O(1) when there are none. */
  protected compactObstacles(): void {
    this.lineAt.compact(this.lineList);
    this.pointAt.compact(this.pointList);
  }

  /** Copy all state into `target` (a fresh Simulator of the same class). */
  protected copyInto(target: SimState): void {
    this.compactObstacles();
    target.now = this.now;
    target.frictionG = this.frictionG;
    target.gravX = this.gravX;
    target.gravY = this.gravY;
    target.store = this.store.clone();
    target.grid = this.grid.clone();
    target.heap = this.heap.cloneWith(target);
    target.lineList = this.lineList.slice();
    target.pointList = this.pointList.slice();
    target.lineAt.reset();
    target.pointAt.reset();
    target.globalLines = this.globalLines;
    target.obstStamp = new Int32Array(this.obstStamp.length);
    target.dirty = this.dirty;
    target.gridBodies = this.gridBodies;
    Object.assign(target.tally, this.tally);
    target.zeno.load(this.zeno.save());
  }

  // ---- motion -------------------------------------------------------------------------------

  /** Start a new motion of body s at time t from (x, y) with velocity (vx, vy). */
  protected setMotion(s: number, t: number, x: number, y: number, vx: number, vy: number): void {
    // Small enough for V8 to inline: the doubles reach the body below unboxed (see MOTION_ARGS).
    const a = MOTION_ARGS;
    a[0] = t;
    a[1] = x;
    a[2] = y;
    a[3] = vx;
    a[4] = vy;
    this.setMotionFromArgs(s);
  }

  /** setMotion with t, x, y, vx, vy in MOTION_ARGS. */
  private setMotionFromArgs(s: number): void {
    this.changes++;
    const a = MOTION_ARGS;
    const t = a[0] as number;
    const x = a[1] as number;
    const y = a[2] as number;
    const vx = a[3] as number;
    const vy = a[4] as number;
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

  // ---- canonical order of simultaneous events -----------------------------------------------

  /**
   * @internal The event queue's tie-break (TieBreak, frontHeap.ts) for two slots whose next events
   * are at exactly the same time (eventOrder.ts). Public only for the queue, which holds the World.
   */
  tieLess(a: number, c: number): boolean {
    return eventTieLess(this.store, this.lineList, this.pointList, a, c);
  }
}
