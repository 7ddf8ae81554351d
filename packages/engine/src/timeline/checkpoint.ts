/**
 * Keyframes of a TimelineCore, both directions (the Keyframe type and its snapshots: keyframe.ts).
 * takeKeyframe(core, afterActions) appends a keyframe of the core's current point: every
 * recordsPerKeyframe(core) records (drive). After a group of actions the keyframe is owed
 * (oweKeyframe): what only the World's computation would change is noted (its instant, record and
 * Zeno watch), the rest is read when it is taken (settleKeyframe): at the first record after the
 * group, at the next group at another instant, or when anything reads the keyframes
 * (TimelineCore.keyframes). The motion table, the registry and the obstacles change only through
 * those, so the keyframe is the one taking it at once gives; a group applied at the same instant
 * with nothing logged since replaces an owed keyframe without taking it (a scene built one action
 * per apply took a copy of every obstacle per apply). A keyframe after a group of actions holds only
 * what changed since the keyframe before it when it can (keyframeDelta.ts: a scene built one action
 * per instant took a copy of every body per instant). restoreKeyframe(core, k) cuts the computed
 * history back to keyframe k: the World (rebuilt from the keyframe's motions), the motion table,
 * the registry, the records and the counts are as they were when it was taken.
 */
import type { ZenoCounters } from "../sim/zenoWatch.js";
import type { TimelineCore } from "./core.js";
import { type Keyframe, loadMotions, snapshotMotions, snapshotProps, worldAt } from "./keyframe.js";
import { deltaSince, mergeById } from "./keyframeDelta.js";
import { MotionTable } from "./motionTable.js";

/** Records between keyframes: at least this many, so small scenes do not drown in keyframes… */
export const KEYFRAME_MIN_RECORDS = 1024;
/** …and this many per live body, so a keyframe (40 bytes per body) costs about 7 bytes per record.
 *  stateAt replays at most max(KEYFRAME_MIN_RECORDS, this × bodies) records: bounded, whatever the
 *  length of the history. */
export const KEYFRAME_RECORDS_PER_BODY = 6;

/** How many records the core writes between two keyframes. */
export function recordsPerKeyframe(c: TimelineCore): number {
  return Math.max(KEYFRAME_MIN_RECORDS, KEYFRAME_RECORDS_PER_BODY * c.live.size);
}

/** Live body numbers sorted by id: core.sortedLive, with the bodies added since merged in (a sort of
 *  every id per instant made a scene built one disc per instant O(n log n) string comparisons per
 *  apply), or sorted again after a removal. */
function liveOrder(c: TimelineCore): Uint32Array {
  if (c.sortedLive === null) {
    const ids = [...c.live.keys()].sort();
    c.sortedLive = Uint32Array.from(ids, (id) => c.live.get(id) as number);
    c.liveAdded = [];
  } else if (c.liveAdded.length > 0) {
    c.sortedLive = mergeById(c.sortedLive, c.liveAdded, c.bodyIds);
    c.liveAdded = [];
  }
  return c.sortedLive;
}

/** What a keyframe owed after a group of actions notes at once (see the header). */
export interface OwedKeyframe {
  time: number;
  record: number;
  zeno: Readonly<ZenoCounters>;
}

/** A keyframe of the core's point at `time` (the World's, or the owed one's), not appended. One
 *  taken between actions shares the last keyframe's order, props, obstacles (nothing but
 *  motions changed since: an owed keyframe is settled before anything else changes). */
export function keyframeOf(
  c: TimelineCore,
  afterActions: boolean,
  time = c.world.time,
  atTimeLimit = c.atTimeLimit,
  zeno: Readonly<ZenoCounters> = c.world.zenoWatch(),
): Keyframe {
  const w = c.world;
  const list = c.rawKeyframes;
  const prev = list[list.length - 1];
  const share = !afterActions && prev !== undefined;
  const delta = afterActions && prev !== undefined ? deltaSince(c, prev) : null;
  // order and props are shared with a full keyframe before (a delta has none: the live order is
  // the one it stands for)
  const shared = share && prev.full !== null ? prev.full : null;
  const order = delta !== null ? null : (shared?.order ?? liveOrder(c));
  return {
    time,
    record: c.records.length,
    actionCount: c.applied,
    afterActions,
    atTimeLimit,
    counts: { ...c.counts },
    eventTotal: c.eventTotal,
    g: w.g,
    gravity: [w.gx, w.gy],
    full:
      order === null
        ? null
        : {
            order,
            props: shared?.props ?? snapshotProps(c.table, order),
            motions: snapshotMotions(c.table, order),
          },
    delta,
    // a delta: no obstacle changed since prev (deltaSince)
    lines: share || delta !== null ? (prev as Keyframe).lines : w.lines(),
    points: share || delta !== null ? (prev as Keyframe).points : w.points(),
    bodyCount: c.bodyIds.length,
    lineCount: c.lineIds.length,
    pointCount: c.pointIds.length,
    // (never changed once in a keyframe: a restore copies them)
    lineNums: share || delta !== null ? (prev as Keyframe).lineNums : new Map(c.lineNums),
    pointNums: share || delta !== null ? (prev as Keyframe).pointNums : new Map(c.pointNums),
    zeno,
  };
}

/** Append a keyframe of the current point (an owed one is settled first). */
export function takeKeyframe(c: TimelineCore, afterActions: boolean): void {
  settleKeyframe(c);
  c.rawKeyframes.push(keyframeOf(c, afterActions));
}

/** Owe the keyframe after the group of actions just applied (see the header). */
export function oweKeyframe(c: TimelineCore): void {
  c.owed = { time: c.world.time, record: c.records.length, zeno: c.world.zenoWatch() };
}

/** Take the owed keyframe, if any (see the header). */
export function settleKeyframe(c: TimelineCore): void {
  const o = c.owed;
  if (o === null) return;
  c.owed = null;
  c.rawKeyframes.push(keyframeOf(c, true, o.time, false, o.zeno));
}

/** The record of the last keyframe, owed or taken. */
export function lastKeyframeRecord(c: TimelineCore): number {
  if (c.owed !== null) return c.owed.record;
  return (c.rawKeyframes[c.rawKeyframes.length - 1] as Keyframe).record;
}

/** Cut the computed history back to keyframe `k` (see the header). */
export function restoreKeyframe(c: TimelineCore, k: number): void {
  restorePoint(c, c.keyframes[k] as Keyframe, k + 1);
}

/** Cut the computed history back to the point keyframe `kf` holds, keeping the first `kept`
 *  keyframes of the list (those before it, and it when it is one of them). */
export function restorePoint(c: TimelineCore, kf: Keyframe, kept: number): void {
  c.keyframes.length = kept;
  c.rewrites++;
  c.view = null;
  // the spare restart point holds while the history up to it is kept (restartPoint.ts)
  if (c.spare !== null && c.spare.record > kf.record) c.spare = null;
  c.world = kf.world !== undefined ? kf.world.clone() : worldAt(kf, c.bodyIds, c.chains);
  c.records.length = kf.record;
  c.applied = kf.actionCount;
  c.actEvents.length = kf.actionCount;
  c.counts = { ...kf.counts };
  c.eventTotal = kf.eventTotal;
  c.bodyIds.length = kf.bodyCount;
  c.lineIds.length = kf.lineCount;
  c.pointIds.length = kf.pointCount;
  c.live = new Map();
  const order = c.chains.orderOf(kf, c.bodyIds);
  for (const i of order) c.live.set(c.bodyIds[i] as string, i);
  c.sortedLive = order;
  c.liveAdded = [];
  c.lineNums = new Map(kf.lineNums);
  c.pointNums = new Map(kf.pointNums);
  c.table = new MotionTable(Math.max(16, kf.bodyCount));
  loadMotions(kf, c.table, c.chains);
  c.atTimeLimit = kf.atTimeLimit;
  c.groupOpen = kf.afterActions;
  c.idle = false;
  c.lastLogged = kf.record > 0 ? (c.records.time[kf.record - 1] as number) : c.forgotten.lastTime;
  c.lastActionTime = kf.afterActions ? kf.time : Number.NEGATIVE_INFINITY;
  c.eventAfterActions = false;
  c.settled = true;
}
