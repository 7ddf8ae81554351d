/**
 * TimelineReader: the reading half of a Timeline (docs/architecture.md), over its TimelineCore:
 * exact states (stateAt: the last keyframe at or before t, at most max(KEYFRAME_MIN_RECORDS,
 * KEYFRAME_RECORDS_PER_BODY × bodies) records replayed, one closed-form evaluation per body, so its
 * cost does not grow with the length of the history; bodyArraysAt: the bodies the same way, as
 * arrays, going on from its last read when it can: bodyArrays.ts), the event log by time or by
 * index, counts and storage. TimelineObservers (observers.ts) extends it with the subscribers, and
 * Timeline extends that with the changes (apply, setActions, prolong).
 * After forgetBefore the kept history starts at `historyStart` (log entry `firstEvent`); entries keep
 * their global numbers (core.records holds entries firstEvent…): what is refused then is kept.ts.
 */
import type { Action } from "../scene/types.js";
import { type BodyArrays, intoProblem } from "../sim/bodyArrays.js";
import { given } from "../sim/refusalText.js";
import { eventIndex, indexRange, stateTime, timeArg } from "./args.js";
import { ArraysCursor } from "./bodyArrays.js";
import type { TimelineCore } from "./core.js";
import { historyStart } from "./forget.js";
import { earliestReadable, earliestTime, keptIndex, keptTime } from "./kept.js";
import { keyframeBytes } from "./keyframe.js";
import { LogCursor } from "./logCursor.js";
import { MotionCursor } from "./motionCursor.js";
import { bodyPath, headlessBodyPath, type PathPiece } from "./path.js";
import { K_ACTION } from "./records.js";
import { headlessStateAt, stateAt } from "./replay.js";
import type { EventDetail, LogEvent, SceneState, TimelineCounts } from "./types.js";

/**
 * The reading half of a Timeline (Timeline extends it): exact states, the event log and counts.
 * Every time here is absolute, on the timeline's clock (0 = the scene's start). A time or index
 * that is not accepted throws a RangeError naming the method and the argument.
 */
export class TimelineReader {
  /** @internal */
  protected core: TimelineCore;
  /** Where the last stateAt replay stopped: reading forwards replays each record once. */
  private readonly states = new MotionCursor();
  /** Where the last bodyArraysAt replay stopped: reading forwards replays each record once. */
  private readonly arrays = new ArraysCursor();
  /** Where the last log read stopped: reading the log in order replays each record once. */
  private readonly cursor = new LogCursor();

  /** @internal */
  protected constructor(core: TimelineCore) {
    this.core = core;
  }

  /** The absolute time the history is computed up to: `stateAt(t)` accepts 0 <= t <= horizon. */
  get horizon(): number {
    return this.core.horizon;
  }

  /** Whether the log and keyframes are kept (the `history` option; false = headless). */
  get history(): boolean {
    return this.core.history;
  }

  /** Start of the kept history: 0 until `forgetBefore` drops the start of it, then the time of the
   *  keyframe it was cut at. Reads before it throw RangeError; edits before it SceneError. */
  get historyStart(): number {
    return historyStart(this.core);
  }

  /** Index of the first log entry still readable: 0 until `forgetBefore`. Entries keep their
   *  numbers; `event(i)` for i < firstEvent throws RangeError. */
  get firstEvent(): number {
    return this.core.forgotten.records;
  }

  /** The exact state at the absolute time t, historyStart <= t <= horizon (historyStart is 0 until
   *  forgetBefore; without history: from the last logged event or action on). Any other t (NaN, a
   *  non-number) throws RangeError. */
  stateAt(t: number): SceneState {
    const c = this.core;
    const at = stateTime(t, c.horizon, earliestTime(c), "stateAt", "t", earliestReadable(c));
    return c.history ? stateAt(c, at, this.states) : headlessStateAt(c, at);
  }

  /**
   * Every body at the absolute time t as arrays (BodyArrays: ids, x, y, vx, vy, ax, ay, r, m, mu, one
   * entry per body): the same bodies, order (by id) and numbers as `stateAt(t).bodies`, bit for
   * bit, without an object per body; reading forwards (playback) replays only the records since
   * the last read (timeline/bodyArrays.ts). The same times as stateAt, and a refused one throws
   * stateAt's RangeError, naming bodyArraysAt. `into`, a previous result, is
   * reused: the result is `into` itself, updated; its arrays are kept where their length equals the
   * new count, and its `ids` array is kept (the same object) when the ids are unchanged, so
   * `ids !== idsBefore` says the set of bodies changed. An `into` that is not a previous result
   * throws RangeError; nothing is written then.
   */
  bodyArraysAt(t: number, into?: BodyArrays): BodyArrays {
    const c = this.core;
    const at = stateTime(t, c.horizon, earliestTime(c), "bodyArraysAt", "t", earliestReadable(c));
    const problem = intoProblem(into);
    if (problem !== null) throw new RangeError(`bodyArraysAt(into): ${problem}`);
    return this.arrays.read(c, at, into);
  }

  /**
   * The exact path of body `id` over [from, to] (by default the whole kept history, historyStart to
   * horizon): the motions it followed, in time order, each with the span it covers (PathPiece: p(t) =
   * positionAt(t0, x0, vx, ax, min(t, tStop)), the same for y; the same numbers as stateAt). A piece
   * ends where the body's motion changed (its collisions and stops, actions that restarted it);
   * spans where the body does not exist give none, and pieces of no length (several events of the
   * body at one instant) are left out; at `to` a piece shows the body before the actions logged at
   * `to` (stateAt(to) after them). A span of no length (from = to) gives the one point where the
   * body is at that time: one piece, until = from, with the motion after everything logged there
   * (stateAt's), or none when the body does not exist then. Without history only the current
   * motion, from the last logged entry on, can be read. A time outside [historyStart, horizon] (or from > to) throws
   * RangeError naming it, and so does an id no body of this timeline ever had. One pass over the
   * records from `from` to `to` that replays only this body's.
   */
  path(id: string, from: number = this.historyStart, to: number = this.core.horizon): PathPiece[] {
    const c = this.core;
    if (typeof id !== "string" || !c.bodyIds.includes(id))
      throw new RangeError(`path(id): must name a body of this timeline (got ${given(id)})`);
    const start = earliestTime(c);
    const early = earliestReadable(c);
    const t0 = stateTime(from, c.horizon, start, "path", "from", early);
    // a to before from is that, with or without history; before the start only when from is there
    const before = t0 === start ? early : `to must not be before from (${t0})`;
    const t1 = stateTime(to, c.horizon, t0, "path", "to", before);
    return c.history ? bodyPath(c, id, t0, t1) : headlessBodyPath(c, id, t0, t1);
  }

  /** Time of the last event or action computed (where a run that ended idle ends). */
  lastLoggedTime(): number {
    return this.core.lastLogged;
  }

  /** Time of the first LOGGED entry (collision, stop or action) strictly after t, or null when there
   *  is none (always null without history). A lookup in the computed history, not a prediction:
   *  unlike `World.nextEventTime()`, it takes a time, never looks past the horizon (prolong first)
   *  and gives null, not +Infinity. t may be ±Infinity; NaN or a non-number throws RangeError, and
   *  so does a t before historyStart once the start was forgotten (forgetBefore). */
  nextEventTime(t: number): number | null {
    const r = this.core.records;
    const i = r.upperBound(keptTime(this.core, "nextEventTime", "t", timeArg("nextEventTime", "t", t)));
    return i < r.length ? (r.time[i] as number) : null;
  }

  /** Time of the last LOGGED entry (collision, stop or action) strictly before t, or null when there
   *  is none. t may be ±Infinity; NaN or a non-number throws RangeError. After forgetBefore it
   *  answers from the kept log: null when no entry from `firstEvent` on lies before t. */
  prevEventTime(t: number): number | null {
    const r = this.core.records;
    const i = r.lowerBound(timeArg("prevEventTime", "t", t)) - 1;
    return i >= 0 ? (r.time[i] as number) : null;
  }

  /** Number of logged events (collisions, stops and actions) ever, forgotten ones included (the
   *  kept ones are firstEvent…eventCount - 1); 0 without history. */
  get eventCount(): number {
    return this.core.forgotten.records + this.core.records.length;
  }

  /** Index of the first logged entry at or after the absolute time t (eventCount when none): the
   *  number to give event(i) or eventDetail(i) for an entry found by its time (eventsBetween,
   *  nextEventTime). O(log n). t may be ±Infinity; NaN or a non-number throws RangeError, and so
   *  does a t before historyStart once the start was forgotten. */
  eventIndexAt(t: number): number {
    const c = this.core;
    const at = keptTime(c, "eventIndexAt", "t", timeArg("eventIndexAt", "t", t));
    return c.forgotten.records + c.records.lowerBound(at);
  }

  /** The i-th logged entry in time order, firstEvent <= i < eventCount (otherwise RangeError). */
  event(i: number): LogEvent {
    const k = keptIndex(this.core, "event", eventIndex("event", i, this.eventCount));
    return this.cursor.read(this.core, k, k + 1)[0] as LogEvent;
  }

  /** The i-th logged entry with each participating body's exact state just before and just after
   *  it (velocities as the engine computed them: the motion before the entry evaluated at its time,
   *  and the new one; see EventDetail for which bodies, and for actions). The same index and
   *  RangeError as `event(i)`, and the same replay (a forward walk replays each record once). */
  eventDetail(i: number): EventDetail {
    const k = keptIndex(this.core, "eventDetail", eventIndex("eventDetail", i, this.eventCount));
    return this.cursor.detail(this.core, k);
  }

  /** The action the i-th logged event applied (frozen, the object in `actions`), or null when that
   *  event is a collision or a stop: what a log entry of type "action" did. RangeError for an i
   *  outside [firstEvent, eventCount). */
  eventAction(i: number): Action | null {
    const k = keptIndex(this.core, "eventAction", eventIndex("eventAction", i, this.eventCount));
    const r = this.core.records;
    return r.kind[k] === K_ACTION ? (this.core.acts[r.a[k] as number] as Action) : null;
  }

  /** Logged entries with t0 <= time <= t1 (absolute times; ±Infinity allowed), in order. NaN or a
   *  non-number throws RangeError, and so does a t0 before historyStart once the start was
   *  forgotten. From t0 = historyStart: the entries from firstEvent on (entries at that instant
   *  logged before the cut were forgotten). */
  eventsBetween(t0: number, t1: number): LogEvent[] {
    const r = this.core.records;
    const from = r.lowerBound(keptTime(this.core, "eventsBetween", "t0", timeArg("eventsBetween", "t0", t0)));
    return this.cursor.read(this.core, from, r.upperBound(timeArg("eventsBetween", "t1", t1)));
  }

  /** Logged events with index in [start, end) (end clamped to eventCount; Infinity = to the end), in
   *  order: the log in pieces, to write a long one out without holding all of it. Indices must be
   *  whole numbers >= 0 (RangeError); a start below firstEvent throws RangeError. */
  eventRange(start: number, end: number): LogEvent[] {
    const [from, to] = indexRange(start, end);
    const k = keptIndex(this.core, "eventRange", from);
    return this.cursor.read(this.core, k, Math.min(to, this.eventCount) - this.core.forgotten.records);
  }

  /** Collisions and stops by kind, and actions applied, over the computed history: totals since
   *  time 0, what forgetBefore dropped included. */
  counts(): TimelineCounts {
    return { ...this.core.counts };
  }

  /** Bytes of stored history: records and keyframes (the kept ones, after forgetBefore). */
  historyBytes(): number {
    const c = this.core;
    let bytes = c.records.bytes();
    c.keyframes.forEach((kf, k) => {
      bytes += keyframeBytes(kf, c.keyframes[k - 1]);
    });
    return bytes;
  }
}
