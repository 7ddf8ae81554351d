/**
 * World: the public face of the exact simulation (contract in docs/architecture.md): construction
 * and copies, and the queries of bodies at a time, which hold only up to the next event (a later
 * time throws ChapgameError naming `t`).
 *
 * The run loop (`advance`, `nextEventTime`) is runLoop.ts's. Edits (bodies and globals: edits.ts;
 * lines and points: obstacleEdits.ts, checked by placement.ts) happen at the current time and are
 * validated first: invalid input throws ChapgameError naming the field, and changes nothing.
 */
import { type BodyArrays, intoProblem, SortedSlots, writeWorldArrays } from "./bodyArrays.js";
import { motionOf, stateOf } from "./bodyState.js";
import { ChapgameError, SimulationError } from "./errors.js";
import { refused } from "./refusalText.js";
import { RunLoop } from "./runLoop.js";
import { keepAsShapeWitness, WITNESS_OPTIONS } from "./shapeWitness.js";
import { requireWorldLimit } from "./timeLimit.js";
import type { BodyMotion, BodyState, Vec2, WorldOptions } from "./types.js";
import { requireFinite } from "./validate.js";
import { checkWorldOptions } from "./worldOptions.js";
import type { ZenoCounters } from "./zenoWatch.js";

/** What a read's t beyond TIME_MAX's refusal suggests (timeLimit.ts). */
const READ_NO_LIMIT = "read at the World's time, or advance it by events (maxEvents) past TIME_MAX first";

/**
 * The exact simulation at one moving instant: discs, lines, rays, segments and points, a friction
 * field `g` (default 9.81), a gravity field (default [0, 0]) and a clock (`time`, default 0).
 *
 * - Edits (addBody, updateBody, removeBody, addLine, addPoint, setGlobal, ...) happen at the current
 *   time. Invalid input throws a ChapgameError (`path` names the field, `reason` says what is
 *   wrong) and changes nothing.
 * - `advance` processes collisions and stops in time order, up to an absolute time and/or a number
 *   of events; `nextEventTime()` says when the next one will happen without moving the World.
 * - `body`, `bodies` and `bodyArrays` give exact states from each body's last event or edit up to
 *   the next event.
 *   A World keeps no past: a Timeline does (history, time travel, edits in the past).
 * - A state the exact model cannot continue from (a disc resting on a line under gravity, a Zeno
 *   state) throws a SimulationError instead of looping.
 *
 * @example
 * const world = new World({ g: 0 });
 * world.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
 * world.addBody("b", { x: 5, y: 0, r: 1, m: 1 });
 * world.advance({ untilTime: 10 }, (e) => console.log(e.kind, e.time)); // bodyBody 3
 */
export class World extends RunLoop {
  /**
   * A World with no bodies or obstacles. Options: `g` (friction field, default 9.81), `gravity`
   * (default [0, 0]), `time` (default 0, at most TIME_MAX in size), `optimizations` (all on).
   * Throws ChapgameError naming a bad option (`g`, `gravity[0]`, `time`) or an unknown key by its own name (`gx`; `options` when the argument is no object).
   */
  constructor(options: WorldOptions = {}) {
    const { g, gravity, time, optimizations } = checkWorldOptions(options);
    super(time, g, gravity[0], gravity[1], optimizations);
  }

  /**
   * @internal A World at a time its own computation reached (a Timeline keyframe), which may lie
   * beyond TIME_MAX: events may take the clock there (a given time or limit may not).
   */
  static restoredAt(time: number, g: number, gravity: Vec2): World {
    const w = new World({ g, gravity });
    w.now = requireFinite("time", time);
    return w;
  }

  /** An independent deep copy (for keyframes). */
  clone(): World {
    // Without `time`: copyInto sets it, and simulation may have taken it past TIME_MAX.
    const w = new World({ g: this.frictionG, gravity: [this.gravX, this.gravY], optimizations: this.opt });
    this.copyInto(w);
    w.index = new Map(this.index);
    return w;
  }

  /** Whether a body with this id exists (a line or a point may have the same id: ids are unique per kind). */
  hasBody(id: string): boolean {
    return this.index.has(id);
  }

  /** Number of bodies. */
  get bodyCount(): number {
    return this.index.size;
  }

  /** @internal The Zeno watch's counters (for Timeline keyframes, which restore them exactly). */
  zenoWatch(): ZenoCounters {
    return this.zeno.save();
  }

  /** @internal Restore counters taken by zenoWatch(). */
  setZenoWatch(w: Readonly<ZenoCounters>): void {
    this.zeno.load(w);
    this.changes++; // whether the next event can be processed may differ
  }

  // ---- queries ----------------------------------------------------------------------------

  /**
   * State of a body at time t (default: now). Exact for t from the body's last event or edit (its
   * current motion's start, `motion(id).t0`) up to the world's next event; a t before that start
   * (or NaN, or an infinite t) throws ChapgameError naming `t` (the World keeps no past: a Timeline
   * does), and so does a t after the next event (the World has not computed it: advance first).
   */
  body(id: string, t: number = this.now): BodyState {
    const s = this.slotOf(id);
    this.requireNoEventBefore(t);
    return stateOf(this.store, s, t);
  }

  /** All bodies at time t (default: now), sorted by id; the same range of t as `body`. */
  bodies(t: number = this.now): BodyState[] {
    this.requireNoEventBefore(t);
    const ids = [...this.index.keys()].sort();
    return ids.map((id) => stateOf(this.store, this.index.get(id) as number, t));
  }

  /**
   * All bodies at time t (default: now) as arrays, one entry per body (BodyArrays): the same bodies,
   * order and numbers as `bodies(t)`, bit for bit, and the same range of t, without an object per
   * body. `into`, a previous result, is reused: the result is `into` itself, updated; its arrays are
   * kept where their length equals the new count, and its `ids` array is kept (the same object)
   * when the ids are unchanged, so `ids !== idsBefore` says the set of bodies changed. A bad t or
   * `into` throws ChapgameError (`t`, `into`) and changes nothing.
   */
  bodyArrays(t: number = this.now, into?: BodyArrays): BodyArrays {
    this.requireNoEventBefore(t);
    const problem = intoProblem(into);
    if (problem !== null) throw new ChapgameError("into", problem);
    return writeWorldArrays(this.store, this.sorted.of(this.store, this.index), t, into);
  }

  /**
   * Throws ChapgameError naming `t` when an event (collision or stop, of any body) not yet
   * processed lies before t: the current motions hold only up to the next event, and a state beyond
   * it would be one the bodies never reach (discs passing through each other), and when t is past
   * both TIME_MAX and now (sim/timeLimit.ts: the state can leave the doubles there). Free for t <= now;
   * otherwise the next event's time comes from `nextEventTime` (which changes nothing, not even the
   * grid an edit sees) and is kept until a change could move it, so a loop of queries pays once.
   */
  private requireNoEventBefore(t: number): void {
    // NaN too: it passed to stateOf, which called it a time before the body's motion (review of
    // session 26), and an empty World gave bodies(NaN) = [] and bodyArrays(NaN).time = NaN
    if (typeof t !== "number" || !Number.isFinite(t)) throw refused("t", "must be a finite time", t);
    if (!(t > this.now)) return;
    requireWorldLimit("t", t, this.now, READ_NO_LIMIT);
    if (this.nextEventChanges !== this.changes) {
      this.nextEventBlocked = "";
      try {
        this.nextEvent = this.nextEventTime();
      } catch (e) {
        // The next event cannot be processed (a Zeno state, a resting contact): states hold up to it.
        if (!(e instanceof SimulationError)) throw e;
        this.nextEvent = e.time;
        this.nextEventBlocked = e.message;
      }
      this.nextEventChanges = this.changes;
    }
    const next = this.nextEvent;
    if (t <= next) return;
    throw new ChapgameError(
      "t",
      this.nextEventBlocked === ""
        ? `must be at or before the next event at ${next} (got ${t}): advance({ untilTime: ${t} }) first, the World computes a state after an event only by processing it`
        : `must be at or before ${next} (got ${t}), where the simulation cannot continue: ${this.nextEventBlocked}`,
    );
  }

  /** The bodies in id order, kept between bodyArrays reads. */
  private readonly sorted = new SortedSlots();

  /** The query range's cache: the next event's time, and `changes` when it was found. */
  private nextEvent = Number.NaN;
  private nextEventBlocked = "";
  private nextEventChanges = -1;

  /**
   * The exact current motion of a body (a copy): p(t) = (x0, y0) + (t - t0) * ((vx, vy) + (t - t0) * (ax, ay) / 2)
   * for t0 <= t <= tStop (positionAt / velocityAt in physics/motion.ts evaluate it bit for bit).
   */
  motion(id: string): BodyMotion {
    return motionOf(this.store, this.slotOf(id));
  }
}

// Kept for the process's lifetime, so that optimised code survives the last World (shapeWitness.ts).
keepAsShapeWitness(new World(WITNESS_OPTIONS));
