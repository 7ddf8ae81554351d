/**
 * The World's edits of bodies and globals (obstacles: obstacleEdits.ts, checked by placement.ts,
 * kept by obstacleUpkeep.ts), made at the current time. Every edit checks its input first: invalid
 * input throws ChapgameError naming the field, and changes nothing. A body edit re-predicts the
 * body at once unless predictions are out of date; a change of globals marks them out of date (the
 * next advance predicts every body).
 */
import { type MotionLaw, motionLaw, positionAt } from "../physics/motion.js";
import { MOTION_MAGNITUDE_MAX } from "../tolerances.js";
import { ChapgameError } from "./errors.js";
import { ObstacleEdits } from "./obstacleEdits.js";
import { given, gravityWithFriction, quoteId, refused } from "./refusalText.js";
import type { BodyInit, BodyMotionInit, BodyPatch, Vec2 } from "./types.js";
import {
  BODY_FIELDS,
  BODY_STATE_EXTRAS,
  checkFrictionGravity,
  finitePlace,
  MOTION_EXTRAS,
  MOTION_FIELDS,
  ownOr,
  requireBounded,
  requireFieldRate,
  requireFields,
  requireFinite,
  requireGravity,
  requireId,
  requireMass,
  requireRadius,
  requireVelocity,
} from "./validate.js";

const restoredLaw: MotionLaw = { ax: 0, ay: 0, tEnd: Number.POSITIVE_INFINITY };

export class Edits extends ObstacleEdits {
  // ---- bodies -------------------------------------------------------------------------------

  /**
   * Add a disc at the current time (`init`: x, y, r, m, and optional mu, vx, vy, each defaulting to
   * 0). Touching is allowed, overlapping another body, a line or a point is not. Throws
   * ChapgameError naming the field: `id` (empty, or a body with it exists), a bad number (`r`,
   * `vx`, ...), an overlap (`x`), an unknown key (`vX`: named alone, as a known field is); nothing changes then.
   */
  addBody(id: string, init: BodyInit): void {
    requireId("id", id);
    requireFields("init", init, BODY_FIELDS, BODY_STATE_EXTRAS);
    if (this.index.has(id)) throw new ChapgameError("id", `a body with id ${quoteId(id)} already exists`);
    const x = requireBounded("x", init.x);
    const y = requireBounded("y", init.y);
    const r = requireRadius("r", init.r);
    const m = requireMass("m", init.m);
    const mu = requireFieldRate("mu", init.mu ?? 0);
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
    this.placeMotion(id, init, true);
  }

  /**
   * @internal addBodyMotion for a motion this World's own computation produced (a Timeline
   * keyframe): no overlap check. A pair pressed together under friction can overlap by more than
   * OVERLAP_REL until one stops (README: what it cannot do), and a restart from a keyframe holding
   * such a pair refused every later edit and undo (review).
   */
  restoreBodyMotion(id: string, init: BodyMotionInit): void {
    this.placeMotion(id, init, false);
  }

  private placeMotion(id: string, init: BodyMotionInit, checkOverlap: boolean): void {
    requireId("id", id);
    requireFields("init", init, MOTION_FIELDS, MOTION_EXTRAS);
    if (this.index.has(id)) throw new ChapgameError("id", `a body with id ${quoteId(id)} already exists`);
    const t0 = requireFinite("t0", init.t0);
    if (t0 > this.now) throw refused("t0", `must be <= the world's time ${this.now}`, t0);
    // A motion the World computed (a Timeline restart) may have left the bounds edits keep to
    // (gravity speeds a body up without limit): only finiteness is required of it.
    const x0 = requireFinite("x0", init.x0);
    const y0 = requireFinite("y0", init.y0);
    const vx = requireFinite("vx", init.vx);
    const vy = requireFinite("vy", init.vy);
    const r = requireRadius("r", init.r);
    const m = requireMass("m", init.m);
    const mu = requireFieldRate("mu", init.mu ?? 0);
    checkFrictionGravity("mu", mu, this.gravity);
    motionLaw(t0, vx, vy, mu, this.frictionG, this.gravX, this.gravY, restoredLaw);
    if (restoredLaw.tEnd < this.now)
      throw new ChapgameError(
        "t0",
        `the motion stops at t=${restoredLaw.tEnd}, before the world's time ${this.now}: give the resting motion that starts at the stop`,
      );
    // Where the body is now, evaluated as xAt/yAt will evaluate it.
    const x = finitePlace("x", t0, positionAt(t0, x0, vx, restoredLaw.ax, this.now), this.now);
    const y = finitePlace("y", t0, positionAt(t0, y0, vy, restoredLaw.ay, this.now), this.now);
    if (checkOverlap) {
      checkMotionMagnitudes(x0, y0, vx, vy);
      checkPlaceNow("x0", "x", x, this.now);
      checkPlaceNow("y0", "y", y, this.now);
      checkDerivedFields(init);
    }
    this.prepareGridFor(x, y, r);
    if (checkOverlap) this.checkOverlap(x, y, r, -1);
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
    this.followStore();
    b.r[s] = r;
    b.m[s] = m;
    b.mu[s] = mu;
    this.setMotion(s, t0, x0, y0, vx, vy);
    this.index.set(id, s);
    this.placeInGrid(s, x, y);
    if (!this.dirty) this.predict(s);
  }

  /**
   * Change a body at the current time: the fields in `patch` are set, the others keep their current
   * values (position and velocity as they are now), and its motion restarts from there, unless the
   * patch changes nothing (empty, or every value equal to the current one): then the motion is kept,
   * so the future is unchanged bit for bit. A moved or
   * grown body must not overlap anything. Throws ChapgameError naming `id` (no such body) or the
   * refused field; nothing changes then. To strike a body: `updateBody(id, { vx, vy })`.
   */
  updateBody(id: string, patch: BodyPatch): void {
    const s = this.slotOf(id);
    requireFields("patch", patch, BODY_FIELDS, BODY_STATE_EXTRAS);
    const b = this.store;
    const now = this.now;
    // Only new values are held to the edit bounds: the body's own current state, left out or
    // passed back, may have left them (gravity speeds a body up without limit).
    const x = ownOr("x", patch.x, this.xAt(s, now), requireBounded);
    const y = ownOr("y", patch.y, this.yAt(s, now), requireBounded);
    const vx = ownOr("vx", patch.vx, this.vxAt(s, now), requireVelocity);
    const vy = ownOr("vy", patch.vy, this.vyAt(s, now), requireVelocity);
    const r = requireRadius("r", patch.r ?? b.r[s]);
    const m = requireMass("m", patch.m ?? b.m[s]);
    const mu = requireFieldRate("mu", patch.mu ?? b.mu[s]);
    checkFrictionGravity("mu", mu, this.gravity);
    // A patch that changes nothing (empty, or a state passed back as it is) keeps the motion: a
    // restart from now would round the same path differently and change the future in its last bits.
    if (
      x === this.xAt(s, now) &&
      y === this.yAt(s, now) &&
      vx === this.vxAt(s, now) &&
      vy === this.vyAt(s, now) &&
      r === b.r[s] &&
      m === b.m[s] &&
      mu === b.mu[s]
    )
      return;
    if (patch.x !== undefined || patch.y !== undefined || patch.r !== undefined) {
      this.prepareGridFor(x, y, r);
      // Name the field that changed (a state passed back whole gives every key).
      const field = x !== this.xAt(s, now) ? "x" : y !== this.yAt(s, now) ? "y" : r !== b.r[s] ? "r" : "x";
      this.checkOverlap(x, y, r, s, field);
    }
    b.r[s] = r;
    b.m[s] = m;
    b.mu[s] = mu;
    this.zeno.push.forget(id);
    this.setMotion(s, now, x, y, vx, vy);
    this.takeFromGrid(s);
    this.placeInGrid(s, x, y);
    if (!this.dirty) this.predict(s);
  }

  /** Remove a body at the current time. Throws ChapgameError naming `id` when there is no such body. */
  removeBody(id: string): void {
    const s = this.slotOf(id);
    this.zeno.push.forget(id);
    this.takeFromGrid(s);
    this.heap.remove(s);
    this.store.release(s);
    this.index.delete(id);
    this.changes++;
  }

  /** Slot of the body `id`; throws ChapgameError naming `id` when there is none. */
  protected slotOf(id: string): number {
    const s = this.index.get(id);
    if (s === undefined) {
      requireId("id", id); // a number or an object: say so, not 'no body with id "1"'
      throw new ChapgameError("id", `no body with id ${quoteId(id)}`);
    }
    return s;
  }

  // ---- globals ------------------------------------------------------------------------------

  /**
   * Change the friction field `g` and/or the gravity field at the current time (a field left out is
   * kept); every body continues from its current position and velocity under the new fields. Each
   * is checked as in WorldOptions (ChapgameError naming `g` or `gravity[i]`); a non-zero gravity is
   * refused while a body has mu > 0 (ChapgameError naming `gravity`, and every such body). Nothing changes on error.
   */
  setGlobal(patch: { g?: number | undefined; gravity?: Vec2 | undefined }): void {
    requireFields("patch", patch, ["g", "gravity"]);
    const g = requireFieldRate("g", patch.g ?? this.frictionG);
    const gravity = requireGravity("gravity", patch.gravity ?? this.gravity);
    if (gravity[0] !== 0 || gravity[1] !== 0) {
      // every body with friction named, as a scene's setGlobal names them (it named only the first
      // added, under the path `bodies.<id>.mu`, no field of this call: review of session 26)
      const withFriction = [...this.index].filter(([, s]) => (this.store.mu[s] as number) > 0);
      if (withFriction.length > 0)
        throw new ChapgameError("gravity", gravityWithFriction(withFriction.map(([id]) => id).sort()));
    }
    const now = this.now;
    const states = [...this.index.values()].map((s) => [
      s,
      this.xAt(s, now),
      this.yAt(s, now),
      this.vxAt(s, now),
      this.vyAt(s, now),
    ]);
    this.zeno.push.clear();
    this.frictionG = g;
    this.gravX = gravity[0];
    this.gravY = gravity[1];
    for (const [s, x, y, vx, vy] of states)
      this.setMotion(s as number, now, x as number, y as number, vx as number, vy as number);
    this.markDirty();
  }
}

/**
 * A user's addBodyMotion's starting position and speed: at most MOTION_MAGNITUDE_MAX in size, the
 * range the contact polynomials work in (beyond it a disc passed through another without an event).
 */
function checkMotionMagnitudes(x0: number, y0: number, vx: number, vy: number): void {
  for (const [path, v] of [
    ["x0", x0],
    ["y0", y0],
    ["vx", vx],
    ["vy", vy],
  ] as const)
    if (Math.abs(v) > MOTION_MAGNITUDE_MAX)
      throw new ChapgameError(
        path,
        `must be at most ${MOTION_MAGNITUDE_MAX} in size (got ${given(v)}): the contact polynomials overflow beyond it`,
      );
}

/** The position `place` (coordinate `axis`) a user's motion gives the body now, in the same range. */
function checkPlaceNow(path: string, axis: string, place: number, now: number): void {
  if (Math.abs(place) > MOTION_MAGNITUDE_MAX)
    throw new ChapgameError(
      path,
      `the motion puts the body at ${axis} = ${place} at the world's time ${now}, beyond ${MOTION_MAGNITUDE_MAX} in size: the contact polynomials overflow there`,
    );
}

/**
 * What a user's addBodyMotion must also hold (a Timeline's own restarts are exempt): the derived
 * ax, ay, tStop, when given, equal to what the World derives from the motion (restoredLaw), since
 * they are not settable: a different value was silently ignored. The place now is not held to the
 * edit bounds, since a state the World reached itself may lie beyond them (magnitude.test.ts).
 */
function checkDerivedFields(init: BodyMotionInit): void {
  const derived = init as BodyMotionInit & { ax?: unknown; ay?: unknown; tStop?: unknown };
  for (const [path, given, want] of [
    ["ax", derived.ax, restoredLaw.ax],
    ["ay", derived.ay, restoredLaw.ay],
    ["tStop", derived.tStop, restoredLaw.tEnd],
  ] as const)
    if (given !== undefined && given !== want)
      throw refused(
        path,
        `is derived from vx, vy, mu and the World's g and gravity (here ${want}), not set: leave it out or pass motion(id)'s own value`,
        given,
      );
}
