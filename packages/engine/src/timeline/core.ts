/**
 * TimelineCore: the computation and storage behind a Timeline. It owns the World at the horizon,
 * the sorted action list (applied ones and scheduled ones), the compact history (records.ts,
 * keyframe.ts, motionTable.ts) and the goals that say how far to compute (goals.ts).
 *
 * drive() advances the World event by event, applies each group of actions when the computation
 * reaches its time (actionGroup.ts: validated first against the scene at that time), copies every
 * event into a record (record, the World's per-event callback) and takes keyframes (checkpoint.ts,
 * which also restores them). Because the World is deterministic and splitting an advance changes
 * nothing, the history only depends on the actions and how far it was computed, never on how the
 * computation was sliced or restarted from a keyframe.
 */

import type { SceneView } from "../scene/sceneRules.js";
import type { Action, Vec2 } from "../scene/types.js";
import type { AdvanceLimits, AdvanceResult, WorldEvent } from "../sim/types.js";
import { World } from "../sim/world.js";
import { applyGroup } from "./actionGroup.js";
import {
  lastKeyframeRecord,
  type OwedKeyframe,
  recordsPerKeyframe,
  settleKeyframe,
  takeKeyframe,
} from "./checkpoint.js";
import { type Goal, satisfied } from "./goals.js";
import type { Keyframe } from "./keyframe.js";
import { ChainCache } from "./keyframeChain.js";
import { MotionTable } from "./motionTable.js";
import { K_ACTION, K_BODY_BODY, K_BODY_LINE, K_BODY_POINT, K_STOP, Records } from "./records.js";
import type { TimelineCounts } from "./types.js";
import type { UndoBase } from "./undoReplay.js";

const INF = Number.POSITIVE_INFINITY;

const KIND_CODE = {
  bodyBody: K_BODY_BODY,
  bodyLine: K_BODY_LINE,
  bodyPoint: K_BODY_POINT,
  stop: K_STOP,
} as const;

/** A group's checked scene, and the point of the computation it holds for (actionGroup.ts). */
export interface OpenView {
  view: SceneView;
  world: World;
  applied: number;
  events: number;
  records: number;
}

function emptyCounts(): TimelineCounts {
  return { bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0, action: 0 };
}

export class TimelineCore {
  readonly history: boolean;
  /** actions given to setActions are applied and their untils honoured as the computation goes */
  readonly eager: boolean;
  /** each action's until becomes a goal when the action is applied (eager, or the untils option) */
  readonly untils: boolean;
  readonly g0: number;
  readonly gravity0: Vec2;
  world: World;
  /** sorted by time, ties in insertion order */
  acts: Action[] = [];
  /** eventTotal when each applied action was applied */
  actEvents: number[] = [];
  applied = 0;
  table = new MotionTable();
  bodyIds: string[] = [];
  live = new Map<string, number>();
  lineIds: string[] = [];
  lineNums = new Map<string, number>();
  pointIds: string[] = [];
  pointNums = new Map<string, number>();
  records = new Records();
  /** the keyframes taken (keyframes: the same, with an owed one taken first) */
  rawKeyframes: Keyframe[] = [];
  /** the read caches of the delta keyframes' chains (keyframeChain.ts): this core's own, so they go
   *  with it and no other Timeline's reads evict them; forgetBefore clears them */
  readonly chains = new ChainCache();
  /** the keyframe owed after the last group of actions, not yet taken (checkpoint.ts) */
  owed: OwedKeyframe | null = null;
  /** A restart point that is not in the keyframe list (restartPoint.ts): the keyframe after the
   *  first actions of an instant that later calls added to, or the point before an instant's
   *  actions; null when none, or when the history before it was cut. */
  spare: Keyframe | null = null;
  /** the scene the last group of actions was checked against, kept for the next group at the same
   *  instant (actionGroup.ts openView) */
  view: OpenView | null = null;
  /** Without history: the newest point an undo restarts from (undoReplay.ts), null until an edit
   *  takes one. */
  undoBase: UndoBase | null = null;
  /** No computation threw since the core was built or restored (a prolong that meets a Zeno state
   *  keeps what it computed, where the World stopped inside an event: a point no recomputation
   *  stops at, so an undo there copies the World: undo.ts). */
  settled = true;
  /** During an apply at or after the horizon: its instant, where the spare restart point may be
   *  taken before the instant's actions (restartPoint.ts). */
  spareAt: number | null = null;
  counts = emptyCounts();
  eventTotal = 0;
  goals: Goal[] = [];
  /** Goals of actions' untils met only because nothing was left to happen (satisfied's "idle"
   *  with no time limit, fewer events than asked): with a later action known, building from scratch
   *  keeps such a goal, so the next group of actions applied revives them (actionGroup.ts). */
  dormant: Goal[] = [];
  /** every event at world.time is processed (the last advance stopped at its time limit, and no
   *  action was applied since) */
  atTimeLimit = true;
  /** a group of actions was applied at world.time and nothing was computed since: an action at the
   *  same time joins that group (as it would when building from scratch) */
  groupOpen = false;
  /** nothing is queued in the World */
  idle = true;
  /** time of the last event or action */
  lastLogged = 0;
  /** time of the last group of actions applied (-Infinity: none), and whether an event was computed
   *  after it: without history (no records) this is how appendsAt knows that an action at the
   *  horizon would come after events that instant's earlier actions caused */
  lastActionTime = Number.NEGATIVE_INFINITY;
  eventAfterActions = false;
  /** The actions at time 0 were checked against the scene rules from an empty scene with this
   *  core's g and gravity, in apply order (parseScene did: Timeline.fromScene): the first group,
   *  when it is at time 0, is not checked again (the same rules on the same scene; a million bodies
   *  took seconds). Cleared by the first group applied. */
  startChecked = false;
  /** how to name action k in error messages */
  pathOf: (k: number) => string = (k) => `actions[${k}]`;
  /** Counts the changes to records or keyframes other than appends (a cut, a restore, a replaced
   *  keyframe): a reader that keeps a replay position (logCursor.ts) starts again when it moves. */
  rewrites = 0;
  /** What forgetBefore dropped (forget.ts): how many records (record i of `records` is log entry
   *  `records + i`), and the time and kind of the last of them (kind -1: none). */
  forgotten = { records: 0, lastTime: 0, lastKind: -1 };
  /** live body numbers sorted by id (cache; null after a removal), but for the bodies added since
   *  (liveAdded: checkpoint.ts liveOrder merges them in; only appended to, or replaced by a new
   *  array, so that an undo gives it back by its length: undo.ts) */
  sortedLive: Uint32Array | null = null;
  liveAdded: number[] = [];
  private readonly onEvent: (e: WorldEvent) => void;

  constructor(g: number, gravity: Vec2, history: boolean, eager: boolean, untils = eager) {
    this.g0 = g;
    this.gravity0 = gravity;
    this.history = history;
    this.eager = eager;
    this.untils = untils;
    this.world = new World({ g, gravity });
    this.onEvent = (e) => this.record(e);
    if (history) takeKeyframe(this, false);
  }

  /** The keyframes, the owed one taken first (checkpoint.ts): every reader sees them all. */
  get keyframes(): Keyframe[] {
    if (this.owed !== null) settleKeyframe(this);
    return this.rawKeyframes;
  }

  set keyframes(list: Keyframe[]) {
    this.rawKeyframes = list;
  }

  get horizon(): number {
    return this.world.time;
  }

  /** Whether an action at time t is applied by computing forward from the horizon (no restore): t
   *  after the horizon, or at it when the last entry logged is before t or is an action. Without
   *  history (nothing to restore), at the horizon unless actions were applied at t and events were
   *  computed after them (the new action would come after events its group caused). */
  appendsAt(t: number): boolean {
    if (t !== this.horizon) return t > this.horizon;
    if (!this.history) return !(this.lastActionTime === t && this.eventAfterActions);
    const r = this.records;
    const last = r.length - 1;
    const kind = last >= 0 ? (r.kind[last] as number) : this.forgotten.lastKind;
    const time = last >= 0 ? (r.time[last] as number) : this.forgotten.lastTime;
    return kind < 0 || time < t || kind === K_ACTION;
  }

  // ---- recording ------------------------------------------------------------------------------

  private record(e: WorldEvent): void {
    // the keyframe owed after the actions holds the motions before this event (nothing else
    // changed since: the World only computes)
    if (this.owed !== null) settleKeyframe(this);
    this.eventTotal++;
    this.counts[e.kind]++;
    this.lastLogged = e.time;
    this.eventAfterActions = true;
    if (!this.history) return;
    const w = this.world;
    const ia = this.live.get(e.a) as number;
    const sa = w.body(e.a);
    this.table.rebase(ia, e.time, sa.vx, sa.vy, w.g, w.gx, w.gy);
    const kind = KIND_CODE[e.kind];
    if (kind === K_BODY_BODY) {
      const ib = this.live.get(e.b as string) as number;
      const sb = w.body(e.b as string);
      this.table.rebase(ib, e.time, sb.vx, sb.vy, w.g, w.gx, w.gy);
      this.records.push(e.time, kind, ia, ib, sa.vx, sa.vy, sb.vx, sb.vy);
    } else {
      const other =
        kind === K_BODY_LINE
          ? (this.lineNums.get(e.b as string) as number)
          : kind === K_BODY_POINT
            ? (this.pointNums.get(e.b as string) as number)
            : 0;
      this.records.push(e.time, kind, ia, other, sa.vx, sa.vy, 0, 0);
    }
  }

  // ---- computing --------------------------------------------------------------------------------

  /** Whether goal g is still open; a goal met by idleness alone becomes dormant (untils only). */
  keep(g: Goal): boolean {
    const how = satisfied(this, g);
    if (how === null) return true;
    if (this.untils && how === "idle" && g.tLimit === INF && this.eventTotal < g.eLimit) this.dormant.push(g);
    return false;
  }

  /** Whether a scheduled action is due now. */
  due(): boolean {
    return (
      this.applied < this.acts.length &&
      (this.atTimeLimit || this.groupOpen) &&
      (this.acts[this.applied] as Action).time === this.world.time
    );
  }

  /** Apply the scheduled actions due now (at the World's time), computing nothing. */
  applyDue(): void {
    if (this.due()) applyGroup(this);
  }

  /**
   * Compute until every goal (and `focus`) is met, at most `budget` collisions and stops. Returns the
   * number of events done and how `focus` was met (null when the budget ran out first).
   */
  drive(budget: number, focus: Goal | null): { events: number; reason: "events" | "idle" | "time" | null } {
    // a throw leaves the core unsettled (see `settled`) until a restore
    const settled = this.settled;
    this.settled = false;
    const res = this.computeGoals(budget, focus);
    this.settled = settled;
    return res;
  }

  private computeGoals(
    budget: number,
    focus: Goal | null,
  ): { events: number; reason: "events" | "idle" | "time" | null } {
    let events = 0;
    for (;;) {
      if (this.due()) {
        applyGroup(this);
        continue;
      }
      this.goals = this.goals.filter((g) => this.keep(g));
      const reason = focus ? satisfied(this, focus) : "idle";
      const actionsPending = this.eager && this.applied < this.acts.length;
      if (reason !== null && this.goals.length === 0 && !actionsPending) return { events, reason };
      if (events >= budget) return { events, reason: null };
      let untilTime = INF;
      let maxEvents = budget - events;
      for (const g of focus && reason === null ? [focus, ...this.goals] : this.goals) {
        if (g.tLimit < untilTime) untilTime = g.tLimit;
        if (g.eLimit - this.eventTotal < maxEvents) maxEvents = g.eLimit - this.eventTotal;
      }
      if (this.applied < this.acts.length)
        untilTime = Math.min(untilTime, (this.acts[this.applied] as Action).time);
      else if (this.idle && untilTime === INF) return { events, reason: "idle" };
      if (this.history)
        maxEvents = Math.min(
          maxEvents,
          recordsPerKeyframe(this) - (this.records.length - lastKeyframeRecord(this)),
        );
      const limits: { untilTime?: number; maxEvents?: number } = {};
      if (untilTime < INF) limits.untilTime = untilTime;
      if (maxEvents < INF) limits.maxEvents = Math.max(0, maxEvents);
      const res = this.advanceWorld(limits);
      events += res.events;
      this.atTimeLimit = res.reason !== "events";
      this.groupOpen = false;
      this.idle = res.reason === "idle";
      if (this.history && this.records.length - lastKeyframeRecord(this) >= recordsPerKeyframe(this))
        takeKeyframe(this, false);
    }
  }

  /** world.advance (advanceReached: a horizon events took past TIME_MAX is recomputed to), without the call when it cannot do anything: no body, and no time to pass (the
   *  World would rebuild its grid around its obstacles, once per action of a scene built one
   *  obstacle per apply; nothing moves, nothing is logged, and the grid decides no result). */
  advanceWorld(limits: AdvanceLimits): AdvanceResult {
    const w = this.world;
    if (w.bodyCount === 0 && limits.untilTime === w.time) return { events: 0, reason: "idle" };
    return w.advanceReached(limits, this.onEvent);
  }
}
