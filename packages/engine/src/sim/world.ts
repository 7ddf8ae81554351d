/**
 * World: the public face of the exact simulation (contract in docs/architecture.md).
 *
 * Edits (add/update/remove bodies, lines, points; globals) happen at the current time and are
 * validated first: invalid input throws ChapgameError naming the field, and changes nothing.
 * `advance` processes events in time order; events exactly at `untilTime` are processed.
 */
import { type MotionLaw, motionLaw, positionAt, velocityAt } from "../physics/motion.js";
import { ChapgameError } from "./errors.js";
import { Placement } from "./placement.js";
import type {
  AdvanceLimits,
  AdvanceResult,
  BodyInit,
  BodyMotionInit,
  BodyPatch,
  BodyState,
  Vec2,
  WorldEvent,
  WorldOptions,
} from "./types.js";
import {
  checkFrictionGravity,
  requireBounded,
  requireFinite,
  requireId,
  requireMass,
  requireNonNegativeBounded,
  requireRadius,
  requireVec,
  requireVelocity,
} from "./validate.js";

const INF = Number.POSITIVE_INFINITY;
const restoredLaw: MotionLaw = { ax: 0, ay: 0, tEnd: INF };

export class World extends Placement {
  constructor(options: WorldOptions = {}) {
    const g = requireNonNegativeBounded("g", options.g ?? 9.81);
    const gravity = requireVec("gravity", options.gravity ?? [0, 0]);
    const time = requireFinite("time", options.time ?? 0);
    super(time, g, gravity[0], gravity[1], options.optimizations ?? {});
  }

  get gravity(): Vec2 {
    return [this.gravX, this.gravY];
  }

  /** An independent deep copy (for keyframes). */
  clone(): World {
    const w = new World({
      g: this.frictionG,
      gravity: [this.gravX, this.gravY],
      time: this.now,
      optimizations: this.opt,
    });
    this.copyInto(w);
    w.index = new Map(this.index);
    return w;
  }

  hasBody(id: string): boolean {
    return this.index.has(id);
  }

  /** Number of bodies. */
  get bodyCount(): number {
    return this.index.size;
  }

  // ---- bodies -------------------------------------------------------------------------------

  addBody(id: string, init: BodyInit): void {
    requireId("id", id);
    if (this.index.has(id)) throw new ChapgameError("id", `a body with id '${id}' already exists`);
    const x = requireBounded("x", init.x);
    const y = requireBounded("y", init.y);
    const r = requireRadius("r", init.r);
    const m = requireMass("m", init.m);
    const mu = requireNonNegativeBounded("mu", init.mu ?? 0);
    const vx = requireVelocity("vx", init.vx ?? 0);
    const vy = requireVelocity("vy", init.vy ?? 0);
    checkFrictionGravity("mu", mu, this.gravity);
    this.prepareGridFor(x, y, r);
    this.checkOverlap(x, y, r, -1);
    this.insertBody(id, r, m, mu, this.now, x, y, vx, vy, x, y);
  }

  /**
   * Add a body with an exact motion that started at `t0 <= time` (what `motion(id)` reports, plus
   * r, m, mu): a World rebuilt this way from every body's motion, the obstacles and the globals
   * computes the same future, bit for bit, as the World the motions came from (every prediction is
   * a pure function of the motions). A friction motion must not have stopped before `time`. Round-off
   * overlaps up to OVERLAP_REL of the contact distance, which collisions leave between bodies in
   * contact, are accepted; larger overlaps are refused like addBody's.
   */
  addBodyMotion(id: string, init: BodyMotionInit): void {
    requireId("id", id);
    if (this.index.has(id)) throw new ChapgameError("id", `a body with id '${id}' already exists`);
    const t0 = requireFinite("t0", init.t0);
    if (t0 > this.now) throw new ChapgameError("t0", `must be <= the world's time ${this.now}`);
    // A motion the World computed (a Timeline restart) may have left the bounds edits keep to
    // (gravity speeds a body up without limit): only finiteness is required of it.
    const x0 = requireFinite("x0", init.x0);
    const y0 = requireFinite("y0", init.y0);
    const vx = requireFinite("vx", init.vx);
    const vy = requireFinite("vy", init.vy);
    const r = requireRadius("r", init.r);
    const m = requireMass("m", init.m);
    const mu = requireNonNegativeBounded("mu", init.mu ?? 0);
    checkFrictionGravity("mu", mu, this.gravity);
    motionLaw(t0, vx, vy, mu, this.frictionG, this.gravX, this.gravY, restoredLaw);
    if (restoredLaw.tEnd < this.now)
      throw new ChapgameError(
        "t0",
        `the motion stops at t=${restoredLaw.tEnd}, before the world's time ${this.now}: give the resting motion that starts at the stop`,
      );
    // Where the body is now, evaluated as xAt/yAt will evaluate it.
    const x = requireFinite("x0", positionAt(t0, x0, vx, restoredLaw.ax, this.now));
    const y = requireFinite("y0", positionAt(t0, y0, vy, restoredLaw.ay, this.now));
    this.prepareGridFor(x, y, r);
    this.checkOverlap(x, y, r, -1, true);
    this.insertBody(id, r, m, mu, t0, x0, y0, vx, vy, x, y);
  }

  /** Store a validated body with motion (t0, x0, y0, vx, vy), now at (x, y), and predict it. */
  private insertBody(
    id: string,
    r: number,
    m: number,
    mu: number,
    t0: number,
    x0: number,
    y0: number,
    vx: number,
    vy: number,
    x: number,
    y: number,
  ): void {
    const b = this.store;
    const s = b.allocate(id);
    this.grid.reserve(b.capacity);
    this.heap.reserve(b.capacity);
    b.r[s] = r;
    b.m[s] = m;
    b.mu[s] = mu;
    this.setMotion(s, t0, x0, y0, vx, vy);
    this.index.set(id, s);
    this.grid.insert(s, this.cellAt(x, y));
    if (!this.dirty) this.predict(s);
  }

  /** @internal The Zeno watch's counters (for Timeline keyframes, which restore them exactly). */
  zenoWatch(): [number, number, number, number] {
    return this.zeno.save();
  }

  /** @internal Restore counters taken by zenoWatch(). */
  setZenoWatch(w: readonly [number, number, number, number]): void {
    this.zeno.load(w);
  }

  updateBody(id: string, patch: BodyPatch): void {
    const s = this.slotOf(id);
    const b = this.store;
    const now = this.now;
    // Only the fields the patch gives are held to the edit bounds: the body's own current state
    // may have left them (gravity speeds a body up without limit).
    const x = patch.x !== undefined ? requireBounded("x", patch.x) : this.xAt(s, now);
    const y = patch.y !== undefined ? requireBounded("y", patch.y) : this.yAt(s, now);
    const vx = patch.vx !== undefined ? requireVelocity("vx", patch.vx) : this.vxAt(s, now);
    const vy = patch.vy !== undefined ? requireVelocity("vy", patch.vy) : this.vyAt(s, now);
    const r = requireRadius("r", patch.r ?? b.r[s]);
    const m = requireMass("m", patch.m ?? b.m[s]);
    const mu = requireNonNegativeBounded("mu", patch.mu ?? b.mu[s]);
    checkFrictionGravity("mu", mu, this.gravity);
    if (patch.x !== undefined || patch.y !== undefined || patch.r !== undefined) {
      this.prepareGridFor(x, y, r);
      this.checkOverlap(x, y, r, s);
    }
    b.r[s] = r;
    b.m[s] = m;
    b.mu[s] = mu;
    this.setMotion(s, now, x, y, vx, vy);
    this.grid.move(s, this.cellAt(x, y));
    if (!this.dirty) this.predict(s);
  }

  removeBody(id: string): void {
    const s = this.slotOf(id);
    this.grid.remove(s);
    this.heap.remove(s);
    this.store.release(s);
    this.index.delete(id);
  }

  /**
   * State of a body at time t (default: now). Exact for t from the body's last event or edit (its
   * current motion's start, `motion(id).t0`) up to its next event; a t before that start (or NaN)
   * throws ChapgameError naming `t` (the World keeps no past: a Timeline does).
   */
  body(id: string, t: number = this.now): BodyState {
    return this.stateOf(this.slotOf(id), t);
  }

  /** All bodies at time t (default: now), sorted by id. */
  bodies(t: number = this.now): BodyState[] {
    const ids = [...this.index.keys()].sort();
    return ids.map((id) => this.stateOf(this.index.get(id) as number, t));
  }

  private stateOf(s: number, t: number): BodyState {
    const b = this.store;
    if (!(t >= (b.mot[s * 8 + 0] as number)))
      throw new ChapgameError(
        "t",
        `must be a time at or after ${b.ids[s]}'s last event or edit (t0 = ${b.mot[s * 8 + 0]}; got ${t}): earlier states are not kept by a World (a Timeline keeps them)`,
      );
    const tEnd = b.mot[s * 8 + 7] as number;
    const te = Math.min(t, tEnd);
    const t0 = b.mot[s * 8 + 0] as number;
    const ax = b.mot[s * 8 + 5] as number;
    const ay = b.mot[s * 8 + 6] as number;
    const moving = t < tEnd;
    return {
      id: b.ids[s] as string,
      x: positionAt(t0, b.mot[s * 8 + 1] as number, b.mot[s * 8 + 3] as number, ax, te),
      y: positionAt(t0, b.mot[s * 8 + 2] as number, b.mot[s * 8 + 4] as number, ay, te),
      vx: moving ? velocityAt(t0, b.mot[s * 8 + 3] as number, ax, t) : 0,
      vy: moving ? velocityAt(t0, b.mot[s * 8 + 4] as number, ay, t) : 0,
      ax: moving ? ax : 0,
      ay: moving ? ay : 0,
      r: b.r[s] as number,
      m: b.m[s] as number,
      mu: b.mu[s] as number,
    };
  }

  /**
   * The exact current motion of a body (a copy): p(t) = (x0, y0) + (t - t0) * ((vx, vy) + (t - t0) * (ax, ay) / 2)
   * for t0 <= t <= tStop (positionAt / velocityAt in physics/motion.ts evaluate it bit for bit).
   */
  motion(id: string): {
    t0: number;
    x0: number;
    y0: number;
    vx: number;
    vy: number;
    ax: number;
    ay: number;
    tStop: number;
  } {
    const s = this.slotOf(id);
    const b = this.store;
    return {
      t0: b.mot[s * 8 + 0] as number,
      x0: b.mot[s * 8 + 1] as number,
      y0: b.mot[s * 8 + 2] as number,
      vx: b.mot[s * 8 + 3] as number,
      vy: b.mot[s * 8 + 4] as number,
      ax: b.mot[s * 8 + 5] as number,
      ay: b.mot[s * 8 + 6] as number,
      tStop: b.mot[s * 8 + 7] as number,
    };
  }

  private slotOf(id: string): number {
    const s = this.index.get(id);
    if (s === undefined) throw new ChapgameError("id", `no body with id '${id}'`);
    return s;
  }

  // ---- globals ------------------------------------------------------------------------------

  setGlobal(patch: { g?: number; gravity?: Vec2 }): void {
    const g = requireNonNegativeBounded("g", patch.g ?? this.frictionG);
    const gravity = requireVec("gravity", patch.gravity ?? this.gravity);
    for (const [id, s] of this.index)
      checkFrictionGravity(`bodies.${id}.mu`, this.store.mu[s] as number, gravity);
    const now = this.now;
    const _b = this.store;
    const states = [...this.index.values()].map((s) => [
      s,
      this.xAt(s, now),
      this.yAt(s, now),
      this.vxAt(s, now),
      this.vyAt(s, now),
    ]);
    this.frictionG = g;
    this.gravX = gravity[0];
    this.gravY = gravity[1];
    for (const [s, x, y, vx, vy] of states)
      this.setMotion(s as number, now, x as number, y as number, vx as number, vy as number);
    this.dirty = true;
  }

  // ---- simulation ---------------------------------------------------------------------------

  advance(limits: AdvanceLimits = {}, onEvent?: (e: WorldEvent) => void): AdvanceResult {
    const untilTime = limits.untilTime ?? INF;
    const maxEvents = limits.maxEvents ?? INF;
    if (Number.isNaN(untilTime) || untilTime < this.now)
      throw new ChapgameError("untilTime", `must be >= the current time ${this.now}`);
    if (Number.isNaN(maxEvents) || maxEvents < 0)
      throw new ChapgameError("maxEvents", "must be a number >= 0");
    this.prepare();
    let events = 0;
    while (events < maxEvents) {
      const r = this.stepOnce(untilTime, onEvent);
      if (r < 0) break;
      events += r;
    }
    if (events >= maxEvents && maxEvents !== INF) return { events, reason: "events" };
    if (untilTime !== INF) this.now = untilTime;
    return { events, reason: this.heap.size === 0 ? "idle" : "time" };
  }

  /**
   * Time of the next collision or stop (+Infinity when nothing will ever happen); throws what
   * advancing to it would throw. Changes nothing observable. Costs O(1) per internal item (cell
   * crossing, stale prediction) before that event, processed in place and undone; only while
   * predictions are out of date (before the first advance, or after an edit of obstacles or
   * globals or a grid rebuild) does it cost a copy of the world and predicting every body, as the
   * next advance will.
   */
  nextEventTime(): number {
    if (!this.dirty) return this.peekEventTime();
    const probe = this.clone();
    let t = INF;
    probe.advance({ maxEvents: 1 }, (e) => {
      t = e.time;
    });
    return t;
  }

  private prepare(): void {
    if (!this.dirty) return;
    this.rebuildGrid();
    this.predictAll();
  }
}
