/**
 * TimelineCore: the computation and storage behind a Timeline. It owns the World at the horizon,
 * the sorted action list (applied ones and scheduled ones), the compact history (records.ts,
 * keyframe.ts, motionTable.ts) and the goals that say how far to compute.
 *
 * drive() advances the World event by event, applies each group of actions when the computation
 * reaches its time (validating it first against the scene at that time: sceneRules.ts), copies every
 * event into a record and takes keyframes. Because the World is deterministic and splitting an advance
 * changes nothing, the history only depends on the actions and how far it was computed, never on how
 * the computation was sliced or restarted from a keyframe.
 */
import { checkAndApply, SceneView } from "../scene/sceneRules.js";
import type { Action, Until, Vec2 } from "../scene/types.js";
import type { WorldEvent } from "../sim/types.js";
import { World } from "../sim/world.js";
import { applyToWorld, touchedBodies } from "./applyAction.js";
import { type Keyframe, loadMotions, snapshotMotions, snapshotProps, worldAt } from "./keyframe.js";
import { MotionTable } from "./motionTable.js";
import { K_ACTION, K_BODY_BODY, K_BODY_LINE, K_BODY_POINT, K_STOP, Records } from "./records.js";
import type { TimelineCounts } from "./types.js";

const INF = Number.POSITIVE_INFINITY;

/** Records between keyframes: at least this many, so small scenes do not drown in keyframes… */
export const KEYFRAME_MIN_RECORDS = 1024;
/** …and this many per live body, so a keyframe (40 bytes per body) costs about 7 bytes per record.
 *  stateAt replays at most max(KEYFRAME_MIN_RECORDS, this × bodies) records: bounded, whatever the
 *  length of the history. */
export const KEYFRAME_RECORDS_PER_BODY = 6;

/** Compute at least until `tLimit` or until `eLimit` collisions and stops in total, whichever first
 *  (or until nothing is left to happen). */
export interface Goal {
  tLimit: number;
  eLimit: number;
}

const KIND_CODE = {
  bodyBody: K_BODY_BODY,
  bodyLine: K_BODY_LINE,
  bodyPoint: K_BODY_POINT,
  stop: K_STOP,
} as const;

export function emptyCounts(): TimelineCounts {
  return { bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0, action: 0 };
}

export class TimelineCore {
  readonly history: boolean;
  /** actions given to setActions are applied and their untils honoured as the computation goes */
  readonly eager: boolean;
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
  keyframes: Keyframe[] = [];
  counts = emptyCounts();
  eventTotal = 0;
  goals: Goal[] = [];
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
  /** how to name action k in error messages */
  pathOf: (k: number) => string = (k) => `actions[${k}]`;
  /** Counts the changes to records or keyframes other than appends (a cut, a restore, a replaced
   *  keyframe): a reader that keeps a replay position (logCursor.ts) starts again when it moves. */
  rewrites = 0;
  /** live body numbers sorted by id (cache; null after an add or remove) */
  sortedLive: Uint32Array | null = null;
  private readonly onEvent: (e: WorldEvent) => void;

  constructor(g: number, gravity: Vec2, history: boolean, eager: boolean) {
    this.g0 = g;
    this.gravity0 = gravity;
    this.history = history;
    this.eager = eager;
    this.world = new World({ g, gravity });
    this.onEvent = (e) => this.record(e);
    if (history) this.keyframe(false);
  }

  get horizon(): number {
    return this.world.time;
  }

  // ---- recording ------------------------------------------------------------------------------

  private record(e: WorldEvent): void {
    this.eventTotal++;
    this.counts[e.kind]++;
    this.lastLogged = e.time;
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

  private liveOrder(): Uint32Array {
    if (this.sortedLive === null) {
      const ids = [...this.live.keys()].sort();
      this.sortedLive = Uint32Array.from(ids, (id) => this.live.get(id) as number);
    }
    return this.sortedLive;
  }

  keyframe(afterActions: boolean): void {
    const w = this.world;
    const prev = this.keyframes[this.keyframes.length - 1];
    const share = !afterActions && prev !== undefined;
    const order = share ? prev.order : this.liveOrder();
    this.keyframes.push({
      time: w.time,
      record: this.records.length,
      actionCount: this.applied,
      afterActions,
      atTimeLimit: this.atTimeLimit,
      counts: { ...this.counts },
      eventTotal: this.eventTotal,
      g: w.g,
      gravity: [w.gx, w.gy],
      order,
      props: share ? prev.props : snapshotProps(this.table, order),
      motions: snapshotMotions(this.table, order),
      lines: share ? prev.lines : w.lines(),
      points: share ? prev.points : w.points(),
      bodyCount: this.bodyIds.length,
      lineCount: this.lineIds.length,
      pointCount: this.pointIds.length,
      lineNums: new Map(this.lineNums),
      pointNums: new Map(this.pointNums),
      zeno: w.zenoWatch(),
    });
  }

  private recordsPerKeyframe(): number {
    return Math.max(KEYFRAME_MIN_RECORDS, KEYFRAME_RECORDS_PER_BODY * this.live.size);
  }

  // ---- actions ----------------------------------------------------------------------------------

  /** Apply every scheduled action at the World's current time (validated first). */
  private applyGroup(): void {
    const w = this.world;
    const t = w.time;
    const groupStart = this.records.length;
    const view = SceneView.of({
      time: t,
      g: w.g,
      gravity: w.gravity,
      bodies: w.bodies(),
      lines: w.lines(),
      points: w.points(),
    });
    while (this.applied < this.acts.length && (this.acts[this.applied] as Action).time === t) {
      const k = this.applied;
      const a = this.acts[k] as Action;
      const path = this.pathOf(k);
      checkAndApply(view, a, path);
      applyToWorld(w, a, path);
      this.track(a, t);
      this.actEvents[k] = this.eventTotal;
      this.counts.action++;
      this.lastLogged = t;
      if (this.history) this.records.push(t, K_ACTION, k, 0, 0, 0, 0, 0);
      if (this.eager && a.until) this.goals.push(this.goalFrom(a.until, t));
      this.applied++;
    }
    this.idle = false;
    // events at t that the actions cause are still to be processed (advance up to t does it)
    this.atTimeLimit = false;
    this.groupOpen = true;
    if (!this.history) return;
    // Actions applied one call at a time at the same instant (an editor or a script adding bodies)
    // would stack one keyframe each: the previous one is redundant when nothing happened since.
    const last = this.keyframes[this.keyframes.length - 1] as Keyframe;
    if (this.keyframes.length > 1 && last.afterActions && last.time === t && last.record === groupStart) {
      this.keyframes.pop();
      this.rewrites++;
    }
    this.keyframe(true);
  }

  /** Update the registry and the motion table after action `a` at time t. */
  private track(a: Action, t: number): void {
    const w = this.world;
    if (a.type === "removeBody") {
      this.live.delete(a.id);
      this.sortedLive = null;
    } else if (a.type === "addBody") {
      this.live.set(a.id, this.bodyIds.length);
      this.bodyIds.push(a.id);
      this.table.ensure(this.bodyIds.length);
      this.sortedLive = null;
    } else if (a.type === "addLine") {
      this.lineNums.set(a.id, this.lineIds.length);
      this.lineIds.push(a.id);
    } else if (a.type === "removeLine") this.lineNums.delete(a.id);
    else if (a.type === "addPoint") {
      this.pointNums.set(a.id, this.pointIds.length);
      this.pointIds.push(a.id);
    } else if (a.type === "removePoint") this.pointNums.delete(a.id);
    if (!this.history) return;
    const touched = touchedBodies(a);
    const ids = touched === "all" ? [...this.live.keys()] : touched === null ? [] : [touched];
    for (const id of ids)
      this.table.setFromState(this.live.get(id) as number, t, w.body(id), w.g, w.gx, w.gy);
  }

  goalFrom(until: Until, t: number): Goal {
    return {
      tLimit: until.time === undefined ? INF : t + until.time,
      eLimit: until.events === undefined ? INF : this.eventTotal + until.events,
    };
  }

  // ---- computing --------------------------------------------------------------------------------

  satisfied(g: Goal): "events" | "idle" | "time" | null {
    if (this.eventTotal >= g.eLimit) return "events";
    const t = this.world.time;
    // "idle": no event is left, and an action still to be applied is one
    if (t > g.tLimit || (t === g.tLimit && this.atTimeLimit))
      return this.idle && this.applied === this.acts.length ? "idle" : "time";
    if (this.idle && this.applied === this.acts.length && g.tLimit === INF) return "idle";
    return null;
  }

  /** Whether a scheduled action is due now. */
  private due(): boolean {
    return (
      this.applied < this.acts.length &&
      (this.atTimeLimit || this.groupOpen) &&
      (this.acts[this.applied] as Action).time === this.world.time
    );
  }

  /**
   * Compute until every goal (and `focus`) is met, at most `budget` collisions and stops. Returns the
   * number of events done and how `focus` was met (null when the budget ran out first).
   */
  drive(budget: number, focus: Goal | null): { events: number; reason: "events" | "idle" | "time" | null } {
    let events = 0;
    for (;;) {
      if (this.due()) {
        this.applyGroup();
        continue;
      }
      this.goals = this.goals.filter((g) => this.satisfied(g) === null);
      const reason = focus ? this.satisfied(focus) : "idle";
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
      if (this.history) {
        const last = this.keyframes[this.keyframes.length - 1] as Keyframe;
        maxEvents = Math.min(maxEvents, this.recordsPerKeyframe() - (this.records.length - last.record));
      }
      const limits: { untilTime?: number; maxEvents?: number } = {};
      if (untilTime < INF) limits.untilTime = untilTime;
      if (maxEvents < INF) limits.maxEvents = Math.max(0, maxEvents);
      const res = this.world.advance(limits, this.onEvent);
      events += res.events;
      this.atTimeLimit = res.reason !== "events";
      this.groupOpen = false;
      this.idle = res.reason === "idle";
      if (this.history) {
        const last = this.keyframes[this.keyframes.length - 1] as Keyframe;
        if (this.records.length - last.record >= this.recordsPerKeyframe()) this.keyframe(false);
      }
    }
  }

  // ---- time travel ------------------------------------------------------------------------------

  /**
   * Cut the computed history back to keyframe `k`: the World (rebuilt from the keyframe's motions),
   * the motion table, the registry, the records and the counts are as they were when it was taken.
   */
  restoreKeyframe(k: number): void {
    const kf = this.keyframes[k] as Keyframe;
    this.keyframes.length = k + 1;
    this.rewrites++;
    this.world = worldAt(kf, this.bodyIds);
    this.records.length = kf.record;
    this.applied = kf.actionCount;
    this.actEvents.length = kf.actionCount;
    this.counts = { ...kf.counts };
    this.eventTotal = kf.eventTotal;
    this.bodyIds.length = kf.bodyCount;
    this.lineIds.length = kf.lineCount;
    this.pointIds.length = kf.pointCount;
    this.live = new Map();
    for (const i of kf.order) this.live.set(this.bodyIds[i] as string, i);
    this.sortedLive = kf.order;
    this.lineNums = new Map(kf.lineNums);
    this.pointNums = new Map(kf.pointNums);
    this.table = new MotionTable(Math.max(16, kf.bodyCount));
    loadMotions(kf, this.table);
    this.atTimeLimit = kf.atTimeLimit;
    this.groupOpen = kf.afterActions;
    this.idle = false;
    this.lastLogged = kf.record > 0 ? (this.records.time[kf.record - 1] as number) : 0;
  }

  /** Goals of the applied actions' untils, as they stand at the current point (after a restore). */
  reopenGoals(): void {
    this.goals = [];
    if (!this.eager) return;
    for (let k = 0; k < this.applied; k++) {
      const a = this.acts[k] as Action;
      if (!a.until) continue;
      const g: Goal = {
        tLimit: a.until.time === undefined ? INF : a.time + a.until.time,
        eLimit: a.until.events === undefined ? INF : (this.actEvents[k] as number) + a.until.events,
      };
      if (this.satisfied(g) === null) this.goals.push(g);
    }
  }
}
