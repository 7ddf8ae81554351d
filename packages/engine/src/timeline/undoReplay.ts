/**
 * How the undo of an edit computing forward (undo.ts) gives back the World without copying it up
 * front: a copy per apply cost O(bodies) each, so a scene built one disc per apply took quadratic
 * time (4,000 discs: 2 s). The edit keeps the point it started from (pointOf); when it throws,
 * - untouchedSince: nothing reached the World (no event, no action applied, the clock where it
 *   was: the action was refused by its checks, which run before the World changes), and the World
 *   is kept as it is;
 * - otherwise the World is recomputed: from the newest restart point before that point (the last
 *   keyframe, or the spare restart point when newer; without history the undo base below), by
 *   replayTo, which computes exactly as far as the point (its instant, events, actions applied and
 *   whether every event at the instant was processed or its group just applied), whatever goals
 *   the edits that led there had. The computation is deterministic and splitting it changes nothing,
 *   so the World (and the motion table) it gives has the same future as the one the edit started
 *   from, bit for bit. It costs a restore (O(bodies)) and the records since the restart point (at
 *   most recordsPerKeyframe), on an error only.
 * Without history there is no keyframe: the undo base is a copy of the World at an earlier point
 * (undoBaseFor), taken again by the edit that finds it more than max(1, bodies /
 * UNDO_BASE_BODIES_PER_STEP) steps (events and actions) old: O(UNDO_BASE_BODIES_PER_STEP) per step,
 * amortized, and on an error a replay of at most that many steps (with the free flight between
 * them: a game applying an action a frame to bodies that rarely collide replays up to bodies / 8
 * frames) plus the failed edit's own. A base holds while the computation only went on from it
 * (core.rewrites unchanged: an undo or a restore changes it).
 */
import type { AdvanceLimits } from "../sim/types.js";
import type { World } from "../sim/world.js";
import { applyGroup } from "./actionGroup.js";
import { restorePoint } from "./checkpoint.js";
import type { TimelineCore } from "./core.js";
import type { Keyframe } from "./keyframe.js";
import type { TimelineCounts } from "./types.js";

/** Without history, a new undo base is taken once the last is this many times fewer steps old than
 *  there are bodies (see the header): copying the World costs about as much per body as a step. */
export const UNDO_BASE_BODIES_PER_STEP = 8;

/** A point of the computation (see the header). */
export interface CorePoint {
  world: World;
  time: number;
  events: number;
  applied: number;
  atTimeLimit: boolean;
  groupOpen: boolean;
  records: number;
  /** without history: the undo base the point is recomputed from */
  base: UndoBase | null;
}

/** Where the core's drive loop stands: the flags and times an undo saves and gives back together. */
export interface DriveState {
  atTimeLimit: boolean;
  groupOpen: boolean;
  idle: boolean;
  lastLogged: number;
  lastActionTime: number;
  eventAfterActions: boolean;
}

export function driveStateOf(c: TimelineCore): DriveState {
  return {
    atTimeLimit: c.atTimeLimit,
    groupOpen: c.groupOpen,
    idle: c.idle,
    lastLogged: c.lastLogged,
    lastActionTime: c.lastActionTime,
    eventAfterActions: c.eventAfterActions,
  };
}

export function putDriveState(c: TimelineCore, d: DriveState): void {
  c.atTimeLimit = d.atTimeLimit;
  c.groupOpen = d.groupOpen;
  c.idle = d.idle;
  c.lastLogged = d.lastLogged;
  c.lastActionTime = d.lastActionTime;
  c.eventAfterActions = d.eventAfterActions;
}

/** Without history: a copy of the World at an earlier point of the computation, never changed, and
 *  what the core needs to compute on from there. */
export interface UndoBase {
  world: World;
  rewrites: number;
  time: number;
  events: number;
  applied: number;
  counts: TimelineCounts;
  drive: DriveState;
  bodyCount: number;
  lineCount: number;
  pointCount: number;
}

/** The core's current point; without history with the undo base to recompute it from. */
export function pointOf(c: TimelineCore): CorePoint {
  return {
    world: c.world,
    time: c.world.time,
    events: c.eventTotal,
    applied: c.applied,
    atTimeLimit: c.atTimeLimit,
    groupOpen: c.groupOpen,
    records: c.records.length,
    base: c.history ? null : undoBaseFor(c),
  };
}

/** The undo base (see the header): the last one while it holds and is recent enough, else a new one
 *  at the current point. */
export function undoBaseFor(c: TimelineCore): UndoBase {
  const b = c.undoBase;
  const steps = c.eventTotal + c.applied;
  const fresh = Math.max(1, c.world.bodyCount / UNDO_BASE_BODIES_PER_STEP);
  if (b !== null && b.rewrites === c.rewrites && steps - (b.events + b.applied) < fresh) return b;
  c.undoBase = {
    world: c.world.clone(),
    rewrites: c.rewrites,
    time: c.world.time,
    events: c.eventTotal,
    applied: c.applied,
    counts: { ...c.counts },
    drive: driveStateOf(c),
    bodyCount: c.bodyIds.length,
    lineCount: c.lineIds.length,
    pointCount: c.pointIds.length,
  };
  return c.undoBase;
}

/** Whether the World is still the one of point `p` (see the header). */
export function untouchedSince(c: TimelineCore, p: CorePoint): boolean {
  return (
    c.world === p.world && c.world.time === p.time && c.eventTotal === p.events && c.applied === p.applied
  );
}

/** The number of every live body, line and point, from the id lists (the live one of an id is its
 *  last number) and the World (which holds exactly the live ones). */
export function renumber(c: TimelineCore): void {
  const w = c.world;
  const numbers = (ids: readonly string[], alive: (id: string) => boolean) => {
    const m = new Map<string, number>();
    for (let n = ids.length - 1; n >= 0; n--) {
      const id = ids[n] as string;
      if (!m.has(id) && alive(id)) m.set(id, n);
    }
    return m;
  };
  c.live = numbers(c.bodyIds, (id) => w.hasBody(id));
  c.lineNums = numbers(c.lineIds, (id) => w.hasLine(id));
  c.pointNums = numbers(c.pointIds, (id) => w.hasPoint(id));
}

/**
 * Recompute the World (and with history the motion table) of point `p` (see the header). The core's
 * action list must be the one it had at `p`; its other fields are left as the recomputation leaves
 * them (the undo gives back its own copies of them afterwards).
 */
export function recompute(c: TimelineCore, p: CorePoint): void {
  c.owed = null; // (the point's keyframe owed, if any, is owed again by the recomputation)
  c.spareAt = null;
  c.goals = [];
  c.dormant = [];
  if (p.base !== null) restoreBase(c, p.base);
  else {
    const kfs = c.rawKeyframes;
    const last = kfs[kfs.length - 1] as Keyframe;
    const s = c.spare;
    const spare = s !== null && s.record > last.record && s.record <= p.records && s.actionCount <= p.applied;
    restorePoint(c, spare ? s : last, kfs.length);
  }
  replayTo(c, p);
}

function restoreBase(c: TimelineCore, b: UndoBase): void {
  c.world = b.world.clone();
  c.applied = b.applied;
  c.actEvents.length = b.applied;
  c.eventTotal = b.events;
  c.counts = { ...b.counts };
  c.bodyIds.length = b.bodyCount;
  c.lineIds.length = b.lineCount;
  c.pointIds.length = b.pointCount;
  renumber(c);
  c.sortedLive = null;
  c.view = null;
  putDriveState(c, b.drive);
  c.settled = true; // (a base is taken at a settled point only: pointOf)
}

function lost(p: CorePoint): Error {
  return new Error(
    `timeline: the undo of a failed edit could not recompute the point before it (time ${p.time}, ${p.events} events, ${p.applied} actions)`,
  );
}

/** Compute from the restored point exactly as far as `p` (see the header): its actions in their
 *  groups, the events before its instant, and at its instant every event (atTimeLimit), its group
 *  just applied (groupOpen), or its first events up to p.events. */
function replayTo(c: TimelineCore, p: CorePoint): void {
  for (;;) {
    const w = c.world;
    if (w.time > p.time || c.eventTotal > p.events || c.applied > p.applied) throw lost(p);
    if (
      w.time === p.time &&
      c.eventTotal === p.events &&
      c.applied === p.applied &&
      c.atTimeLimit === p.atTimeLimit &&
      c.groupOpen === p.groupOpen
    )
      return;
    if (c.due() && c.applied < p.applied) {
      applyGroup(c);
      continue;
    }
    let untilTime = p.time;
    if (c.applied < c.acts.length)
      untilTime = Math.min(untilTime, (c.acts[c.applied] as { time: number }).time);
    const limits: AdvanceLimits = { untilTime };
    // stopped inside an instant by an event limit: count the events
    if (!p.atTimeLimit && !p.groupOpen) limits.maxEvents = p.events - c.eventTotal;
    const from = { time: w.time, events: c.eventTotal, atTimeLimit: c.atTimeLimit };
    const res = c.advanceWorld(limits);
    c.atTimeLimit = res.reason !== "events";
    c.groupOpen = false;
    c.idle = res.reason === "idle";
    if (
      c.world.time === from.time &&
      c.eventTotal === from.events &&
      c.atTimeLimit === from.atTimeLimit &&
      !(c.due() && c.applied < p.applied)
    )
      throw lost(p);
  }
}
