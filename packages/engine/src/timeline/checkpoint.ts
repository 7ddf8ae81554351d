/**
 * Keyframes of a TimelineCore, both directions (the Keyframe type and its snapshots: keyframe.ts).
 * takeKeyframe(core, afterActions) appends a keyframe of the core's current point: after every group
 * of actions, and every recordsPerKeyframe(core) records (drive). restoreKeyframe(core, k) cuts the
 * computed history back to keyframe k: the World (rebuilt from the keyframe's motions), the motion
 * table, the registry, the records and the counts are as they were when it was taken.
 */
import type { TimelineCore } from "./core.js";
import { type Keyframe, loadMotions, snapshotMotions, snapshotProps, worldAt } from "./keyframe.js";
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

/** Live body numbers sorted by id (cached in core.sortedLive until a body is added or removed). */
function liveOrder(c: TimelineCore): Uint32Array {
  if (c.sortedLive === null) {
    const ids = [...c.live.keys()].sort();
    c.sortedLive = Uint32Array.from(ids, (id) => c.live.get(id) as number);
  }
  return c.sortedLive;
}

/** Append a keyframe of the current point. One taken between actions shares the previous
 *  keyframe's order, props, lines and points (nothing but motions changed since). */
export function takeKeyframe(c: TimelineCore, afterActions: boolean): void {
  const w = c.world;
  const prev = c.keyframes[c.keyframes.length - 1];
  const share = !afterActions && prev !== undefined;
  const order = share ? prev.order : liveOrder(c);
  c.keyframes.push({
    time: w.time,
    record: c.records.length,
    actionCount: c.applied,
    afterActions,
    atTimeLimit: c.atTimeLimit,
    counts: { ...c.counts },
    eventTotal: c.eventTotal,
    g: w.g,
    gravity: [w.gx, w.gy],
    order,
    props: share ? prev.props : snapshotProps(c.table, order),
    motions: snapshotMotions(c.table, order),
    lines: share ? prev.lines : w.lines(),
    points: share ? prev.points : w.points(),
    bodyCount: c.bodyIds.length,
    lineCount: c.lineIds.length,
    pointCount: c.pointIds.length,
    lineNums: new Map(c.lineNums),
    pointNums: new Map(c.pointNums),
    zeno: w.zenoWatch(),
  });
}

/** Cut the computed history back to keyframe `k` (see the header). */
export function restoreKeyframe(c: TimelineCore, k: number): void {
  const kf = c.keyframes[k] as Keyframe;
  c.keyframes.length = k + 1;
  c.rewrites++;
  c.world = worldAt(kf, c.bodyIds);
  c.records.length = kf.record;
  c.applied = kf.actionCount;
  c.actEvents.length = kf.actionCount;
  c.counts = { ...kf.counts };
  c.eventTotal = kf.eventTotal;
  c.bodyIds.length = kf.bodyCount;
  c.lineIds.length = kf.lineCount;
  c.pointIds.length = kf.pointCount;
  c.live = new Map();
  for (const i of kf.order) c.live.set(c.bodyIds[i] as string, i);
  c.sortedLive = kf.order;
  c.lineNums = new Map(kf.lineNums);
  c.pointNums = new Map(kf.pointNums);
  c.table = new MotionTable(Math.max(16, kf.bodyCount));
  loadMotions(kf, c.table);
  c.atTimeLimit = kf.atTimeLimit;
  c.groupOpen = kf.afterActions;
  c.idle = false;
  c.lastLogged = kf.record > 0 ? (c.records.time[kf.record - 1] as number) : c.forgotten.lastTime;
  c.lastActionTime = kf.afterActions ? kf.time : Number.NEGATIVE_INFINITY;
  c.eventAfterActions = false;
}
