/**
 * Timeline: a scene as a list of actions stamped with times, the computed history up to `horizon`,
 * and exact time travel (contract in docs/architecture.md).
 *
 * - apply(action) validates the action (fields, and the scene rules against the state at its time)
 *   and inserts it. At or after the horizon it computes forward to its time and applies it; before
 *   the horizon it restores the last restart point before its place (a World keyframe, or the spare
 *   one: restartPoint.ts), replays to it, applies it and recomputes up to the old horizon: the result is identical to building from scratch (the World
 *   is deterministic and splitting a computation changes nothing). On any error nothing changes.
 * - The work of apply and setActions on the core: edits.ts (and undo.ts, headlessInstant.ts).
 * - Reading (stateAt, the log, counts): reader.ts; observing (subscribe, getSnapshot): observers.ts.
 *   This class extends TimelineObservers, which extends TimelineReader.
 * - Storage: see records.ts (49 bytes per event) and keyframe.ts.
 * - history: false keeps no log and no keyframes (headless runs); then only the horizon can be read.
 * - forgetBefore(t) drops the start of the history (forget.ts; what the kept part still answers and
 *   accepts: kept.ts), for a game that keeps only its last seconds to rewind.
 */
import { checkAction } from "../scene/action.js";
import { nonNegative } from "../scene/fields.js";
import { applyOrder, parseScene } from "../scene/parse.js";
import type { Action, SceneFile, Until } from "../scene/types.js";
import { SimulationError } from "../sim/errors.js";
import { copyAction, freezeAction, sameUntil } from "./actionData.js";
import {
  checkActionList,
  checkApplyOptions,
  checkBudget,
  checkProlongTo,
  checkUntil,
  checkUntilReach,
} from "./args.js";
import { TimelineCore } from "./core.js";
import { actionsOnCore, applyToCore } from "./edits.js";
import { forgetBefore, forgetTime } from "./forget.js";
import { type Goal, goalFrom } from "./goals.js";
import type { HeadlessInstant } from "./headlessInstant.js";
import { TimelineObservers } from "./observers.js";
import { type CheckedOptions, checkOptions, checkSceneOptions } from "./options.js";
import type { ApplyOptions, ProlongResult, TimelineOptions } from "./types.js";

const INF = Number.POSITIVE_INFINITY;

/**
 * A scene's history with exact time travel: every edit is an Action stamped with a time (on a clock
 * that starts at 0), and the history is computed by a World up to the `horizon`.
 *
 * - `apply(action)` / `setActions(list)` edit; an action before the horizon cuts the computed future
 *   at its time and recomputes it, identical to building from scratch with the action in place.
 * - `prolong({ time, events })` computes further, counting from the horizon; `prolongTo(t)` up to an
 *   absolute time; `prolongSlice` in bounded slices for a UI.
 * - `stateAt(t)` is the exact state at any 0 <= t <= horizon; the log of collisions, stops and
 *   actions is read with `event(i)`, `eventRange`, `eventsBetween`, `nextEventTime(t)`, ...
 * - Refused edits throw a SceneError (a ChapgameError: `path` names the field, `reason` says what
 *   is wrong) and change nothing; a Zeno state throws SimulationError. Reads given a bad time or
 *   index throw RangeError.
 * - `history: false` keeps no log and no keyframes (headless runs): states can be read only from the
 *   last logged event or action up to the horizon.
 * - `forgetBefore(t)` drops the history before the last keyframe at or before t (memory returned);
 *   states from `historyStart` on, log entries from `firstEvent` on and edits after it are
 *   unchanged (entries logged at historyStart before the cut are forgotten too), earlier ones refused.
 *
 * @example
 * const tl = new Timeline({ g: 0 });
 * tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] });
 * tl.apply({ time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 });
 * tl.prolong({ time: 10 });        // horizon 10: a collision at t = 3
 * tl.stateAt(2).bodies;            // exact state at t = 2
 */
export class Timeline extends TimelineObservers {
  private readonly options: CheckedOptions;
  private slice: { until: Until; goal: Goal } | null = null;
  /** without history: the instant at the horizon, so an action there joins its group (headlessInstant.ts) */
  private instant: HeadlessInstant | null = null;
  private actionsView: readonly Action[] | null = null;
  /** the scene's meta (JSON text, so each toScene gets its own copy), kept for toScene */
  private metaJson: string | null = null;

  /**
   * An empty timeline at horizon 0. Options: `g` (friction field, default 9.81), `gravity` (default
   * [0, 0]), `history` (default true), `compute` (default true). Throws SceneError naming a bad
   * option or an unknown key.
   */
  constructor(options: TimelineOptions = {}) {
    const o = checkOptions(options);
    super(new TimelineCore(o.g, o.gravity, o.history, o.compute, o.untils));
    this.options = o;
  }

  /** A timeline of a scene (validated: SceneError naming the field). Options as the constructor's,
   *  without g and gravity (they come from the scene). */
  static fromScene(
    scene: SceneFile | string,
    options: Omit<TimelineOptions, "g" | "gravity"> = {},
  ): Timeline {
    checkSceneOptions(options);
    return Timeline.fromParsedScene(parseScene(scene), options);
  }

  /**
   * @internal A timeline of a scene parseScene returned and nobody changed since (for the CLI, which
   * reads the scene before it builds the timeline): built as fromScene builds it, without
   * validating the scene a second time (a million bodies took seconds each time). The scene's
   * actions are frozen and kept (parseScene made them: no caller holds them to edit).
   */
  static fromParsedScene(s: SceneFile, options: Omit<TimelineOptions, "g" | "gravity"> = {}): Timeline {
    checkSceneOptions(options);
    const tl = new Timeline({ ...options, g: s.g, gravity: s.gravity });
    tl.replaceActions(s.actions.map(freezeAction), true);
    if (s.meta !== undefined) tl.metaJson = JSON.stringify(s.meta);
    return tl;
  }

  /**
   * @internal Whether nothing is left after the horizon: no action scheduled later and no event the
   * World would ever process (exact: `World.nextEventTime`, not the grid's queue). For the CLI's
   * "idle".
   */
  nothingLeft(): boolean {
    const c = this.core;
    if (c.applied < c.acts.length) return false;
    try {
      return c.world.nextEventTime() === INF;
    } catch (e) {
      if (e instanceof SimulationError) return false; // an event that cannot be processed is left
      throw e;
    }
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

  // ---- changes ----------------------------------------------------------------------------------

  /** A new revision: the actions view is made again when read, and every listener is told. */
  private changed(): void {
    this.actionsView = null;
    this.notifyChange();
  }

  /** Validate and apply one action at its time (absolute, >= 0; see the header). Throws SceneError
   *  (`action.<field>`), or SimulationError when the recomputed history meets a Zeno state before
   *  the horizon; then nothing changes. When it would make a later action invalid, the error names
   *  that one as `actions[i]` (its index in `actions`) and says so. Without history, an action before
   *  the horizon is refused (`action.time`). */
  apply(action: Action, options: ApplyOptions = {}): void {
    const a = freezeAction(checkAction(action, "action"));
    const { keepHorizon, checkLater } = checkApplyOptions(options);
    this.instant = applyToCore(this.core, a, keepHorizon, checkLater, this.instant);
    this.slice = null;
    this.changed();
  }

  /** Replace the whole action list (undo/redo, paste), atomically, computing up to at least the
   *  current horizon. The history is kept up to the first action that differs from the current list
   *  (compared by value, in applying order: time, then as given): when that lies after the horizon
   *  (or at it, joining that instant's actions, unless events they caused were computed) nothing is
   *  cut and the computation goes on from the horizon, as apply's would; otherwise it is recomputed
   *  from the last restart point before it: a World keyframe, or the spare one kept between (or just
   *  before) the actions of the instant last edited (restartPoint.ts), so that taking back or
   *  replacing the last action at the horizon restarts at its instant. A `compute: false` timeline
   *  computes nothing further: its horizon stays, or goes back to that restart point (to 0 without
   *  history or keyframe), for the caller to prolong. The timeline's own actions (from `actions`)
   *  are taken as they are, the others checked. A refused action throws SceneError naming `actions[i]` (its index in the
   *  list given, also when a later prolong applies it), a Zeno state before the horizon
   *  SimulationError; either way nothing changes. */
  setActions(actions: readonly Action[]): void {
    // The timeline's own actions (from `actions`: frozen, deep, after checkAction made them) are
    // taken as they are: an editor giving back its list with one action changed checked every
    // other one again (6,000 actions: 20 ms per edit).
    const own = new Set(this.core.acts);
    this.replaceActions(
      checkActionList(actions).map((a, i) =>
        own.has(a as Action) ? (a as Action) : freezeAction(checkAction(a, `actions[${i}]`)),
      ),
    );
  }

  /** setActions with the actions already checked (checkAction) and frozen; `startChecked`: their
   *  scene rules at time 0 too (parseScene's, from an empty scene: fromScene), so a timeline built
   *  from scratch does not check them again (TimelineCore.startChecked). */
  private replaceActions(checked: readonly Action[], startChecked = false): void {
    const order = applyOrder(checked);
    const sorted = order.map((i) => checked[i] as Action);
    this.instant = null;
    const o = this.options;
    const fresh = () => {
      const core = new TimelineCore(o.g, o.gravity, o.history, o.compute, o.untils);
      core.startChecked = startChecked;
      return core;
    };
    this.core = actionsOnCore(this.core, sorted, order, fresh);
    this.slice = null;
    this.changed();
  }

  /** Compute further from the current horizon: `until.time` seconds COUNTED FROM THE HORIZON
   *  (relative: at horizon 5, `prolong({ time: 2 })` computes up to 7) and/or `until.events` more
   *  collisions and stops, whichever comes first; neither = until nothing is left to happen (a scene
   *  that never comes to rest then runs for ever). For an absolute time use `prolongTo(t)`, as
   *  `World.advance({ untilTime })` is. A bad `until` throws SceneError (`until.time`,
   *  `until.events`), as does a time that takes the horizon past TIME_MAX (sim/timeLimit.ts: go past it
   *  by events). A Zeno state on the way throws SimulationError; what was computed up to it
   *  is kept and the subscribers are told. */
  prolong(until: Until): ProlongResult {
    const u = checkUntil(until, "until");
    checkUntilReach(u, this.core.horizon, "until");
    const res = this.compute(INF, goalFrom(this.core, u, this.core.horizon));
    return { events: res.events, reason: res.reason ?? "events" };
  }

  /** Compute up to the ABSOLUTE time t (the clock of the actions' times and of stateAt), if the
   *  horizon is before it; otherwise nothing is computed (`events: 0`). Unlike `prolong({ time })`,
   *  which counts from the horizon; like `World.advance({ untilTime })`. t must be a finite number
   *  >= 0, and at most TIME_MAX when past the horizon (SceneError naming `t`; sim/timeLimit.ts). A Zeno state throws SimulationError, as for prolong. */
  prolongTo(t: number): ProlongResult {
    nonNegative({ t }, "t", "");
    checkProlongTo(t, this.core.horizon);
    const res = this.compute(INF, { tLimit: t, eLimit: INF });
    return { events: res.events, reason: res.reason ?? "events" };
  }

  /** Incremental prolong for UIs: at most `budget` events per call; call with the same `until` until
   *  done (the target is fixed by the first call: `until.time` counts from the horizon at that call,
   *  as in prolong). A bad `until` or `budget` (a whole number >= 1, or Infinity) throws SceneError. */
  prolongSlice(
    until: Until,
    budget: number,
  ): { done: boolean; events: number; horizon: number; reason?: ProlongResult["reason"] } {
    const u = checkUntil(until, "until");
    checkBudget(budget);
    const pending = this.slice && sameUntil(this.slice.until, u);
    if (!pending) checkUntilReach(u, this.core.horizon, "until");
    const goal = this.slice && pending ? this.slice.goal : goalFrom(this.core, u, this.core.horizon);
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
    // computed past the instant: its record (a World copy) is no longer needed
    if (this.instant !== null && this.core.horizon > this.instant.time) this.instant = null;
    this.changed();
    return res;
  }

  /** Forget the history before the last keyframe at or before t, 0 <= t <= horizon (RangeError
   *  otherwise), returning its memory (a game rewinding 2 s: `forgetBefore(Math.max(0, horizon - 2))`
   *  now and then). Returns the kept start, `historyStart` (<= t): states from there on, entries
   *  from `firstEvent` on and edits after it are unchanged, earlier ones refused (kept.ts; entries
   *  logged at historyStart before the cut are forgotten too). Entry numbers, counts, actions and
   *  toScene stay. A t before historyStart: nothing changes, historyStart is returned. No history:
   *  nothing changes, the horizon is returned (historyStart stays 0). The subscribers are told
   *  when something was dropped. */
  forgetBefore(t: number): number {
    const { start, dropped } = forgetBefore(this.core, forgetTime(t, this.core.horizon));
    if (dropped) this.changed();
    return start;
  }
}
