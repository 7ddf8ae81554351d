/**
 * Timeline: a scene as a list of actions stamped with times, the computed history up to `horizon`,
 * and exact time travel (contract in docs/architecture.md).
 *
 * - apply(action) validates the action (fields, and the scene rules against the state at its time)
 *   and inserts it. At or after the horizon it computes forward to its time and applies it; before
 *   the horizon it restores the last World keyframe before its time, replays to it, applies it and
 *   recomputes up to the old horizon: the result is identical to building from scratch (the World
 *   is deterministic and splitting a computation changes nothing). On any error nothing changes.
 * - stateAt(t) costs one keyframe load (O(bodies)) + at most KEYFRAME_RECORDS_PER_BODY records per
 *   body + one closed-form evaluation per body.
 * - Storage: see records.ts (49 bytes per event) and keyframe.ts.
 * - history: false keeps no log and no keyframes (headless runs); then only the horizon can be read.
 */
import { checkAction } from "../scene/action.js";
import { SceneError } from "../scene/errors.js";
import { nonNegative } from "../scene/fields.js";
import { applyOrder, parseScene } from "../scene/parse.js";
import type { Action, SceneFile, Until } from "../scene/types.js";
import { copyAction, freezeAction, restartKeyframe, sameUntil } from "./actionData.js";
import {
  checkActionList,
  checkBudget,
  checkUntil,
  eventIndex,
  indexRange,
  stateTime,
  timeArg,
} from "./args.js";
import { type Goal, TimelineCore } from "./core.js";
import { type Keyframe, keyframeBytes } from "./keyframe.js";
import { notifyAll } from "./listeners.js";
import { MotionTable } from "./motionTable.js";
import { type CheckedOptions, checkOptions, checkSceneOptions } from "./options.js";
import { K_ACTION } from "./records.js";
import { headlessStateAt, logEvents, stateAt } from "./replay.js";
import type { LogEvent, ProlongResult, SceneState, TimelineCounts, TimelineOptions } from "./types.js";
import { saveCore } from "./undo.js";

const INF = Number.POSITIVE_INFINITY;

export class Timeline {
  private core: TimelineCore;
  private readonly options: CheckedOptions;
  private revision = 0;
  private readonly listeners = new Set<() => void>();
  private readonly scratch = new MotionTable();
  private slice: { until: Until; goal: Goal } | null = null;
  private actionsView: readonly Action[] | null = null;
  /** the scene's meta (JSON text, so each toScene gets its own copy), kept for toScene */
  private metaJson: string | null = null;

  constructor(options: TimelineOptions = {}) {
    this.options = checkOptions(options);
    const o = this.options;
    this.core = new TimelineCore(o.g, o.gravity, o.history, o.compute);
  }

  /** A timeline of a scene (validated: SceneError naming the field). Options as the constructor's,
   *  without g and gravity (they come from the scene). */
  static fromScene(
    scene: SceneFile | string,
    options: Omit<TimelineOptions, "g" | "gravity"> = {},
  ): Timeline {
    checkSceneOptions(options);
    const s = parseScene(scene);
    const tl = new Timeline({ ...options, g: s.g, gravity: s.gravity });
    tl.setActions(s.actions);
    if (s.meta !== undefined) tl.metaJson = JSON.stringify(s.meta);
    return tl;
  }

  /** The scene file of this timeline (round-trips with fromScene, meta included): a copy, the
   *  caller's to edit. It holds the actions, not how far the history was computed: after fromScene,
   *  prolong again. */
  toScene(): SceneFile {
    const scene: SceneFile = {
      format: "chapgame",
      version: 1,
      g: this.core.g0,
      gravity: [this.core.gravity0[0], this.core.gravity0[1]],
      actions: this.core.acts.map(copyAction),
    };
    if (this.metaJson !== null) scene.meta = JSON.parse(this.metaJson) as Record<string, unknown>;
    return scene;
  }

  /** All actions in the order they apply (time, then insertion order). The same array until a change;
   *  it and its actions are frozen (edit a copy and give it to setActions). */
  get actions(): readonly Action[] {
    if (this.actionsView === null) this.actionsView = Object.freeze([...this.core.acts]);
    return this.actionsView;
  }

  get horizon(): number {
    return this.core.horizon;
  }

  get history(): boolean {
    return this.core.history;
  }

  // ---- changes ----------------------------------------------------------------------------------

  /** A new revision; every listener is told (listeners.ts). */
  private changed(): void {
    this.revision++;
    this.actionsView = null;
    notifyAll(this.listeners);
  }

  /** Validate and apply one action (see the header). Throws SceneError; then nothing changes. When
   *  it would make a later action invalid, the error names that one as `actions[i]` (its index in
   *  `actions`) and says so. */
  apply(action: Action): void {
    const a = freezeAction(checkAction(action, "action"));
    const c = this.core;
    let insertAt = c.acts.length;
    while (insertAt > 0 && (c.acts[insertAt - 1] as Action).time > a.time) insertAt--;
    const last = c.records.length - 1;
    const forward =
      a.time > c.horizon ||
      (a.time === c.horizon &&
        (last < 0 || (c.records.time[last] as number) < a.time || c.records.kind[last] === K_ACTION));
    if (!forward && !c.history)
      throw new SceneError("action.time", `must be >= the horizon ${c.horizon} (history is off)`);
    let k = 0;
    if (!forward) {
      const kfs = c.keyframes;
      for (k = kfs.length - 1; k > 0; k--) {
        const kf = kfs[k] as Keyframe;
        if (kf.time < a.time || (kf.time === a.time && kf.afterActions && kf.actionCount === insertAt)) break;
      }
    }
    const undo = saveCore(c, forward ? c.records.length : (c.keyframes[k] as Keyframe).record);
    try {
      const oldHorizon = c.horizon;
      if (!forward) c.restoreKeyframe(k);
      c.acts.splice(insertAt, 0, a);
      // the others by their index in `actions` as the caller knows it (without this one)
      c.pathOf = (i) => (i === insertAt ? "action" : `actions[${i > insertAt ? i - 1 : i}]`);
      if (!forward) {
        c.reopenGoals();
        c.goals.push({ tLimit: oldHorizon, eLimit: INF });
      }
      c.drive(INF, { tLimit: a.time, eLimit: INF });
      if (!c.eager && a.until) c.goals.push(c.goalFrom(a.until, a.time));
      c.drive(INF, null);
      c.pathOf = (i) => `actions[${i}]`;
    } catch (e) {
      undo();
      if (e instanceof SceneError && e.path.startsWith("actions["))
        throw new SceneError(e.path, `${e.reason} (once this action is in place)`);
      throw e;
    }
    this.slice = null;
    this.changed();
  }

  /** Replace the whole action list (undo/redo, paste), atomically, recomputing up to at least the
   *  current horizon. Only the part after the first changed action is recomputed (from the last World
   *  keyframe before it). Errors name `actions[i]` by the index in `actions`. */
  setActions(actions: readonly Action[]): void {
    const checked = checkActionList(actions).map((a, i) => freezeAction(checkAction(a, `actions[${i}]`)));
    const order = applyOrder(checked);
    const sorted = order.map((i) => checked[i] as Action);
    const c = this.core;
    const oldHorizon = c.horizon;
    const pathOf = (k: number) => `actions[${order[k]}]`;
    const k = c.history && c.eager ? restartKeyframe(c.acts, c.keyframes, sorted) : 0;
    if (k > 0) {
      const undo = saveCore(c, (c.keyframes[k] as Keyframe).record);
      try {
        c.restoreKeyframe(k);
        c.acts = sorted;
        c.pathOf = pathOf;
        c.reopenGoals();
        c.goals.push({ tLimit: oldHorizon, eLimit: INF });
        c.drive(INF, null);
        c.pathOf = (i) => `actions[${i}]`;
      } catch (e) {
        undo();
        throw e;
      }
    } else {
      const o = this.options;
      const core = new TimelineCore(o.g, o.gravity, o.history, o.compute);
      core.acts = sorted;
      core.pathOf = pathOf;
      if (core.eager && oldHorizon > 0) core.goals.push({ tLimit: oldHorizon, eLimit: INF });
      core.drive(INF, null);
      core.pathOf = (i) => `actions[${i}]`;
      this.core = core;
    }
    this.slice = null;
    this.changed();
  }

  /** Compute further from the horizon: `until.time` seconds and/or `until.events` collisions and
   *  stops, whichever first; neither = until nothing is left to happen. */
  prolong(until: Until): ProlongResult {
    const u = checkUntil(until, "until");
    const res = this.compute(INF, this.core.goalFrom(u, this.core.horizon));
    return { events: res.events, reason: res.reason ?? "events" };
  }

  /** Compute up to time t (if not computed yet). */
  prolongTo(t: number): ProlongResult {
    nonNegative({ t }, "t", "");
    const res = this.compute(INF, { tLimit: t, eLimit: INF });
    return { events: res.events, reason: res.reason ?? "events" };
  }

  /** Incremental prolong for UIs: at most `budget` events per call; call with the same `until` until
   *  done (the target is fixed by the first call). */
  prolongSlice(
    until: Until,
    budget: number,
  ): { done: boolean; events: number; horizon: number; reason?: ProlongResult["reason"] } {
    const u = checkUntil(until, "until");
    checkBudget(budget);
    const goal =
      this.slice && sameUntil(this.slice.until, u)
        ? this.slice.goal
        : this.core.goalFrom(u, this.core.horizon);
    const res = this.compute(budget, goal);
    const done = res.reason !== null;
    if (!done) this.slice = { until: u, goal };
    const out: { done: boolean; events: number; horizon: number; reason?: ProlongResult["reason"] } = {
      done,
      events: res.events,
      horizon: this.core.horizon,
    };
    if (res.reason !== null) out.reason = res.reason;
    return out;
  }

  /** Compute (core.drive) and tell the listeners; a pending prolongSlice target is dropped. When the
   *  World throws (a Zeno state), what was computed up to it stays (the horizon moved): the listeners
   *  are told, then the World's error is rethrown (it wins over a listener's). */
  private compute(budget: number, goal: Goal): ReturnType<TimelineCore["drive"]> {
    this.slice = null;
    let res: ReturnType<TimelineCore["drive"]>;
    try {
      res = this.core.drive(budget, goal);
    } catch (error) {
      try {
        this.changed();
      } finally {
        // biome-ignore lint/correctness/noUnsafeFinally: the World's error is the one to report
        throw error;
      }
    }
    this.changed();
    return res;
  }

  // ---- reading ----------------------------------------------------------------------------------

  /** The exact state at t, 0 <= t <= horizon (without history: from the last event or action on). */
  stateAt(t: number): SceneState {
    const c = this.core;
    const at = stateTime(t, c.horizon);
    return c.history ? stateAt(c, at, this.scratch) : headlessStateAt(c, at);
  }

  /** Time of the last event or action computed (where a run that ended idle ends). */
  lastLoggedTime(): number {
    return this.core.lastLogged;
  }

  /** Time of the first logged event strictly after t, or null. */
  nextEventTime(t: number): number | null {
    const r = this.core.records;
    const i = r.upperBound(timeArg("nextEventTime", "t", t));
    return i < r.length ? (r.time[i] as number) : null;
  }

  /** Time of the last logged event strictly before t, or null. */
  prevEventTime(t: number): number | null {
    const r = this.core.records;
    const i = r.lowerBound(timeArg("prevEventTime", "t", t)) - 1;
    return i >= 0 ? (r.time[i] as number) : null;
  }

  /** Number of logged events (collisions, stops and actions); 0 without history. */
  get eventCount(): number {
    return this.core.records.length;
  }

  /** The i-th logged event in time order. */
  event(i: number): LogEvent {
    eventIndex("event", i, this.eventCount);
    return logEvents(this.core, i, i + 1, this.scratch)[0] as LogEvent;
  }

  /** The action the i-th logged event applied (frozen, the object in `actions`), or null when that
   *  event is a collision or a stop: what a log entry of type "action" did. */
  eventAction(i: number): Action | null {
    eventIndex("eventAction", i, this.eventCount);
    const r = this.core.records;
    return r.kind[i] === K_ACTION ? (this.core.acts[r.a[i] as number] as Action) : null;
  }

  /** Logged events with t0 <= time <= t1, in order. */
  eventsBetween(t0: number, t1: number): LogEvent[] {
    const r = this.core.records;
    const from = r.lowerBound(timeArg("eventsBetween", "t0", t0));
    return logEvents(this.core, from, r.upperBound(timeArg("eventsBetween", "t1", t1)), this.scratch);
  }

  /** Logged events with index in [start, end) (end clamped to eventCount; Infinity = to the end), in
   *  order: the log in pieces, to write a long one out without holding all of it. */
  eventRange(start: number, end: number): LogEvent[] {
    const [from, to] = indexRange(start, end);
    return logEvents(this.core, from, Math.min(to, this.eventCount), this.scratch);
  }

  /** Collisions and stops by kind, and actions applied, over the computed history. */
  counts(): TimelineCounts {
    return { ...this.core.counts };
  }

  /** Bytes of stored history: records and keyframes. */
  historyBytes(): number {
    const c = this.core;
    let bytes = c.records.bytes();
    c.keyframes.forEach((kf, k) => {
      bytes += keyframeBytes(kf, c.keyframes[k - 1]);
    });
    return bytes;
  }

  // ---- observing --------------------------------------------------------------------------------

  /** Call `listener` after every change (apply, setActions, prolong). Returns the unsubscribe. A
   *  listener that throws does not stop the others; its error is rethrown after them. */
  subscribe(listener: () => void): () => void {
    if (typeof listener !== "function") throw new TypeError("subscribe: listener must be a function");
    this.listeners.add(listener);
    return () => {
      this.listeners.delete(listener);
    };
  }

  /** Revision number: changes on every change. */
  getSnapshot(): number {
    return this.revision;
  }
}
