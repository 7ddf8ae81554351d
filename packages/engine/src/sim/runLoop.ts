/**
 * The World's run loop: `advance` (collisions and stops in time order, up to a time and/or a number
 * of events, with an `onEvent` callback that may edit the World) and `nextEventTime` (when the next
 * one will happen, changing nothing observable). The processing of one event is simulator.ts's
 * (`stepOnce`); edits are edits.ts's and obstacleEdits.ts's; construction, copies and the queries of
 * bodies are world.ts's. Bad limits throw ChapgameError naming the field before anything changes;
 * an event the exact model cannot process throws SimulationError, the events before it processed.
 */
import { Edits } from "./edits.js";
import { ChapgameError } from "./errors.js";
import { refused } from "./refusalText.js";
import { requireWorldLimit } from "./timeLimit.js";
import type { AdvanceLimits, AdvanceResult, WorldEvent } from "./types.js";
import { requireFields } from "./validate.js";

const INF = Number.POSITIVE_INFINITY;

/** What an untilTime beyond TIME_MAX's refusal suggests (timeLimit.ts). */
const UNTIL_TIME_NO_LIMIT =
  "for no time limit leave it out (or pass Infinity), and bound a run past TIME_MAX by events (maxEvents)";

export abstract class RunLoop extends Edits {
  /** advance is running (its callback may edit the World, not advance it again). */
  private advancing = false;

  /** An independent deep copy (World.clone): what nextEventTime advances when predictions are stale. */
  abstract clone(): RunLoop;

  /**
   * Process collisions and stops in time order, calling `onEvent` with each (one reused object: copy
   * what you keep), until `limits.untilTime` or after `limits.maxEvents` events, whichever comes
   * first; with neither, until nothing is queued (then `time` is the last event's, or where the
   * advance started when it processed none). `untilTime` is an ABSOLUTE time on this World's
   * clock (events exactly at it are processed, then `time` becomes untilTime), unlike
   * `Timeline.prolong({ time })`, which counts from the horizon (`Timeline.prolongTo(t)` is
   * absolute). Bad limits throw ChapgameError (`untilTime` NaN, before `time`, or finite and past
   * both TIME_MAX and `time` (sim/timeLimit.ts): the clock passes TIME_MAX only by events; `maxEvents` not a
   * whole number >= 0 or Infinity; `onEvent` not a function) before anything changes. An event the
   * exact model cannot process throws SimulationError: the events before it stay processed, the
   * World's time is the failing event's (`error.time`) and advancing again throws the same.
   * `onEvent` may edit the World (bodies, obstacles, globals): the edit acts as if this advance had
   * stopped after that event and the edit been made before the next, bit for bit. Calling advance
   * from `onEvent` throws ChapgameError (path `advance`). An error `onEvent` throws ends the
   * advance and is passed on, the World left as after that event (processed, counted, `time` at
   * it; the callback's edits before the throw kept), as maxEvents would leave it.
   */
  advance(limits: AdvanceLimits = {}, onEvent?: (e: WorldEvent) => void): AdvanceResult {
    return this.advanceWithin(limits, onEvent, true);
  }

  /**
   * @internal `advance` for a Timeline, whose limits are its own checked inputs or times its
   * computation already reached, which events may have taken past TIME_MAX (the old horizon an
   * edit in the past recomputes to): TIME_MAX is not asked of them (sim/timeLimit.ts).
   */
  advanceReached(limits: AdvanceLimits, onEvent?: (e: WorldEvent) => void): AdvanceResult {
    return this.advanceWithin(limits, onEvent, false);
  }

  /** advance, with the untilTime held to TIME_MAX when `bounded`. */
  private advanceWithin(
    limits: AdvanceLimits,
    onEvent: ((e: WorldEvent) => void) | undefined,
    bounded: boolean,
  ): AdvanceResult {
    requireFields("limits", limits, ["untilTime", "maxEvents"]);
    const untilTime = limits.untilTime ?? INF;
    const maxEvents = limits.maxEvents ?? INF;
    if (typeof untilTime !== "number" || Number.isNaN(untilTime))
      throw refused("untilTime", `must be a number (a time >= the current time ${this.now})`, untilTime);
    if (untilTime < this.now)
      throw refused("untilTime", `must be >= the current time ${this.now}`, untilTime);
    if (bounded) requireWorldLimit("untilTime", untilTime, this.now, UNTIL_TIME_NO_LIMIT);
    if (
      typeof maxEvents !== "number" ||
      !(maxEvents >= 0) ||
      !(Number.isInteger(maxEvents) || maxEvents === INF)
    )
      throw refused("maxEvents", "must be a whole number >= 0, or Infinity", maxEvents);
    if (onEvent !== undefined && typeof onEvent !== "function")
      throw refused("onEvent", "must be a function called with each event", onEvent);
    if (this.advancing)
      throw new ChapgameError(
        "advance",
        "cannot be called from inside advance's onEvent callback: return from it, then advance again",
      );
    this.prepare();
    let events = 0;
    // The time of the last collision or stop processed (where this advance started: none yet).
    let lastEventTime = this.now;
    this.advancing = true;
    try {
      // Ends: each step processes a collision or stop (counted), or internal work that leads to
      // one: a stale prediction (at most one per body event, since a prediction goes stale only
      // when its partner's motion changed) or a cell crossing (a body crosses finitely many cells
      // before its next event or untilTime: its path to there is bounded, and the edge cells reach
      // to infinity, so a body flying off for ever crosses none once it is outside the grid).
      while (events < maxEvents) {
        const r = this.stepOnce(untilTime, onEvent);
        if (r < 0) break;
        events += r;
        if (r > 0) lastEventTime = this.now;
        // The callback edited obstacles or globals: predict again from here, as the next advance
        // would after an edit between two advances (body edits re-predict their own body at once).
        if (this.dirty) this.prepare();
      }
    } finally {
      this.advancing = false;
    }
    if (events >= maxEvents && maxEvents !== INF) return { events, reason: "events" };
    if (untilTime !== INF) this.now = untilTime;
    else if (this.heap.size === 0 && this.now > lastEventTime) this.rewindIdle(lastEventTime);
    return { events, reason: this.heap.size === 0 ? "idle" : "time" };
  }

  /**
   * Time of the next collision or stop, predicted: the future, from this World's current state
   * (+Infinity when nothing will ever happen). Not to be confused with `Timeline.nextEventTime(t)`,
   * which looks up the next LOGGED event after t in a computed history and gives null when there
   * is none. Throws the SimulationError that advancing to it would throw. Changes nothing observable. Costs O(1) per internal item (cell
   * crossing, stale prediction) before that event, processed in place and undone; only while
   * predictions are out of date (before the first advance, after an edit of globals or of an
   * infinite line or ray, or when an edit of segments and points lays the grid out again
   * (obstacleUpkeep.ts), or after a grid rebuild) does it cost a copy of the world and predicting
   * every body, as the next advance will.
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

  /**
   * The queue ran empty with no time limit, after internal work (cell crossings, stale predictions)
   * later than the last event: put the clock back to that event, so that where an unbounded advance
   * ends does not depend on the grid (a Timeline's horizon is this time, and an action between the
   * two times is valid). Nothing moves between the two times but free flight, and motions start at
   * events or edits, so every state holds; the grid lists bodies where the internal work left them,
   * so the next advance rebuilds it and predicts again (markDirty), as after an obstacle edit.
   */
  private rewindIdle(t: number): void {
    this.now = t;
    this.markDirty();
  }

  private prepare(): void {
    if (!this.dirty && !this.store.trimDue()) return; // removals alone may call for a trim (bodyStore.ts)
    this.fitSlots();
    this.rebuildGrid();
    this.predictAll();
  }
}
