/**
 * saveCore(core, cutRecord, edit?): everything needed to undo the next operation on a TimelineCore,
 * which may cut the records back to `cutRecord` (records.length when it only appends). Returns the
 * undo. apply() and setActions() use it to change nothing when they throw. It holds records by their
 * index: forgetBefore (which renumbers them) must not run between saveCore and its undo; it never
 * does (no Timeline method calls it inside an edit), and the undo refuses to run if it did rather
 * than restore forgotten records inconsistently.
 *
 * Without `edit` everything is copied: O(bodies + actions + keyframes + records after cutRecord).
 * With `edit` (an EditScope: what the operation may change, given by the caller), only what it may
 * change is kept, so that an edit costs O(what it changes and recomputes), not O(every action and
 * keyframe ever) (audit of session 20: a game applying one action a frame slowed down without
 * bound, forgetBefore or not). The scope's promises, which apply() and setActions() keep:
 * - nothing before keyframe `fromKeyframe` changes: every keyframe, body id, line id, point id and
 *   action-event entry before it stays (a restore goes back to that keyframe at most, and computing
 *   only appends after it; the last keyframe can be replaced);
 * - the action list is changed only by inserting one action at `insertAt`, or replaced by a new array;
 * - with `worldReplaced`, the World object and the motion table are replaced (restoreKeyframe)
 *   before anything changes them, so the old ones need no copy; without it, of the motion table
 *   only the rows of the live bodies can change.
 * - `restart`: the keyframe the edit restores when it is not keyframes[fromKeyframe] (the spare
 *   restart point, restartPoint.ts, which goes into the list at `fromKeyframe`).
 * The id → number maps are not copied for a scope: a restore replaces them (new Maps), and an edit
 * computing forward only adds and deletes entries, so its undo rebuilds them from the id lists and
 * the World it gives back (renumber), O(ids) on an error only (a copy per apply made a scene built
 * one obstacle per apply quadratic). The keyframe owed (checkpoint.ts), the spare restart point and
 * the kept view of the scene (actionGroup.ts) are given back or dropped with the rest.
 * Nor is the World copied for an edit computing forward (nor the motion-table rows of the live
 * bodies): that copy, O(bodies) per apply, made a scene built one disc per apply quadratic (4,000
 * discs: 2 s). The undo keeps the World when the edit did not reach it, and otherwise recomputes it
 * from the last restart point (undoReplay.ts: deterministic, so bit for bit), O(bodies + records
 * since that point) on an error only. Only after a computation that threw (core.settled false: a
 * prolong that met a Zeno state, whose World no recomputation stops at) is the World copied as
 * before. Without a scope (the headless instant's group, headlessInstant.ts) everything is copied.
 * The undo must run before any other operation on the core.
 */
import type { TimelineCore } from "./core.js";
import type { Keyframe } from "./keyframe.js";
import { MotionTable, STRIDE } from "./motionTable.js";
import { driveStateOf, pointOf, putDriveState, recompute, renumber, untouchedSince } from "./undoReplay.js";

/** What an edit may change (see the header). */
export interface EditScope {
  fromKeyframe: number;
  insertAt?: number;
  worldReplaced: boolean;
  /**
   * The edit only computes forward from the current point: the id lists and the action events only
   * grow (their tails start at today's lengths, not at keyframe `fromKeyframe`'s counts, which
   * without history is keyframe 0: everything), and the actions inserted since go in one run at
   * `insertAt` (the end of their instant's block). So the undo still holds after more actions were
   * applied at that instant and it was computed further (headlessInstant.ts keeps it for that).
   */
  forward?: boolean;
  restart?: Keyframe;
}

/** An array's elements from `start` on, and how to put them back. */
interface Tail<T> {
  start: number;
  items: T[];
}

function tailOf<T>(list: T[], start: number): Tail<T> {
  return { start, items: list.slice(start) };
}

function putBack<T>(list: T[], tail: Tail<T>): void {
  list.length = tail.start;
  for (const x of tail.items) list.push(x);
}

/** Copies of the motion-table rows of the live bodies, with their numbers. */
function liveRows(c: TimelineCore): { nums: number[]; rows: Float64Array } {
  const nums = [...c.live.values()];
  const rows = new Float64Array(nums.length * STRIDE);
  const d = c.table.data;
  for (let k = 0; k < nums.length; k++) {
    const n = nums[k] as number;
    rows.set(d.subarray(n * STRIDE, (n + 1) * STRIDE), k * STRIDE);
  }
  return { nums, rows };
}

function putRows(data: Float64Array, saved: { nums: number[]; rows: Float64Array }): void {
  for (let k = 0; k < saved.nums.length; k++)
    data.set(saved.rows.subarray(k * STRIDE, (k + 1) * STRIDE), (saved.nums[k] as number) * STRIDE);
}

export function saveCore(c: TimelineCore, cutRecord: number, edit?: EditScope): () => void {
  // (a timeline without history may hold no keyframe at all)
  const kfs = c.rawKeyframes; // (an owed keyframe stays owed: it is saved below)
  const kf: Keyframe | null = edit === undefined ? null : (edit.restart ?? kfs[edit.fromKeyframe] ?? null);
  // where each list's tail starts: 0 (no scope: all of it), today's length (forward), or the
  // restart keyframe's count
  const fwd = edit?.forward === true;
  const start = (list: readonly unknown[], count: number | undefined): number =>
    edit === undefined ? 0 : fwd ? list.length : Math.min(count ?? 0, list.length);
  // forward from a point a recomputation reaches: no copy of the World (undoReplay.ts)
  const point = fwd && c.settled ? pointOf(c) : null;
  const saved = {
    world: edit?.worldReplaced || point !== null ? c.world : c.world.clone(),
    acts: edit === undefined ? c.acts.slice() : c.acts,
    actsLength: c.acts.length,
    actEvents: tailOf(
      c.actEvents,
      fwd ? Math.min(c.applied, c.actEvents.length) : start(c.actEvents, kf?.actionCount),
    ),
    applied: c.applied,
    // the motion table: whole (no scope), untouched (a restore replaces it), recomputed with the
    // World (null), or the rows of the live bodies (the only rows an edit computing forward changes:
    // a body gone keeps its row, and a new body's row lies past the restored ids and is written
    // whole when a body takes it again)
    table: edit === undefined ? c.table.data.slice() : point !== null ? null : c.table.data,
    // (without history the table is not kept: it has no rows)
    rows: edit === undefined || edit.worldReplaced || !c.history || point !== null ? null : liveRows(c),
    bodyIds: tailOf(c.bodyIds, start(c.bodyIds, kf?.bodyCount)),
    live: edit === undefined ? new Map(c.live) : fwd ? null : c.live,
    lineIds: tailOf(c.lineIds, start(c.lineIds, kf?.lineCount)),
    lineNums: edit === undefined ? new Map(c.lineNums) : fwd ? null : c.lineNums,
    pointIds: tailOf(c.pointIds, start(c.pointIds, kf?.pointCount)),
    pointNums: edit === undefined ? new Map(c.pointNums) : fwd ? null : c.pointNums,
    tail: c.records.saveTail(cutRecord),
    keyframes: tailOf(kfs, edit === undefined ? 0 : Math.max(0, Math.min(edit.fromKeyframe, kfs.length))),
    keyframeList: kfs,
    owed: c.owed,
    spare: c.spare,
    counts: { ...c.counts },
    eventTotal: c.eventTotal,
    goals: c.goals.slice(),
    dormant: c.dormant.slice(),
    drive: driveStateOf(c),
    pathOf: c.pathOf,
    sortedLive: c.sortedLive,
    liveAdded: c.liveAdded,
    liveAddedCount: c.liveAdded.length,
    forgotten: c.forgotten.records,
    settled: c.settled,
  };
  const insertAt = edit?.insertAt;
  const restore = (): void => {
    if (point === null) c.world = saved.world;
    c.acts = saved.acts;
    // the actions inserted into the same list since go again (one run at insertAt: see EditScope)
    if (c.acts.length > saved.actsLength && insertAt !== undefined)
      c.acts.splice(insertAt, c.acts.length - saved.actsLength);
    putBack(c.actEvents, saved.actEvents);
    c.applied = saved.applied;
    if (saved.table !== null) {
      c.table = new MotionTable(0);
      c.table.data = saved.table;
      if (saved.rows !== null) putRows(saved.table, saved.rows);
    }
    putBack(c.bodyIds, saved.bodyIds);
    putBack(c.lineIds, saved.lineIds);
    putBack(c.pointIds, saved.pointIds);
    if (saved.live === null || saved.lineNums === null || saved.pointNums === null) renumber(c);
    else {
      c.live = saved.live;
      c.lineNums = saved.lineNums;
      c.pointNums = saved.pointNums;
    }
    c.records.restoreTail(cutRecord, saved.tail);
    c.keyframes = saved.keyframeList;
    putBack(kfs, saved.keyframes);
    c.owed = saved.owed;
    c.spare = saved.spare;
    c.view = null;
    c.rewrites++;
    c.counts = saved.counts;
    c.eventTotal = saved.eventTotal;
    c.goals = saved.goals;
    c.dormant = saved.dormant;
    putDriveState(c, saved.drive);
    // the bodies added since the order was sorted: the same list (only appended to, or replaced by
    // a new one: checkpoint.ts liveOrder), cut back
    c.sortedLive = saved.sortedLive;
    c.liveAdded = saved.liveAdded;
    c.liveAdded.length = saved.liveAddedCount;
    c.pathOf = saved.pathOf;
    c.settled = saved.settled;
  };
  return () => {
    if (c.forgotten.records !== saved.forgotten)
      throw new Error("timeline: the history was forgotten during an edit; its undo cannot restore it");
    const touched = point !== null && !untouchedSince(c, point);
    restore();
    if (!touched) return;
    // the action list, the lists and the counts as they were, then the World recomputed up to the
    // point, then the rest given back again over what the recomputation left
    recompute(c, point);
    restore();
  };
}
