/**
 * The spare restart point of a TimelineCore (core.spare): a keyframe kept out of the keyframe list
 * (readers never see it) so that an edit of the last action applied at an instant restarts there
 * instead of at the last keyframe before the instant (which may lie up to recordsPerKeyframe
 * records back, or at the start: 85 ms of recomputation at 6,000 discs for each merged edit of the
 * editor). It is either
 * - the keyframe after the first actions of an instant, when a later call applied more actions at
 *   the same instant with nothing logged between (actionGroup.ts: the keyframe that group replaced;
 *   restored by rebuilding the World from it, as a keyframe is: copying the World at every such
 *   call made a scene built one disc per apply quadratic), or
 * - the point just before an instant's first actions (noteInstantStart), taken when the last
 *   restart point lies at least SPARE_BODIES_PER_RECORD times fewer records back than there are
 *   live bodies (see there), at the instant of an apply at or after the horizon (an edit in the
 *   past, or a setActions, takes none: taken back, it restarts where it did), with a copy of the
 *   World.
 * Either is a valid restart point for a first change `d` at time `cut` (spareFits): the actions
 * before it are unchanged (actionCount <= d), and it lies before `cut`, or at `cut` after some of
 * that instant's actions (the rest are applied as the same group) or before all of them, every event
 * at `cut` processed. Restoring it (restoreSpare) gives what restoring a keyframe taken there would,
 * so the history is the one building from scratch gives, bit for bit. It is dropped when the
 * history up to it is cut (restoreKeyframe, forgetBefore), kept and given back by an undo (undo.ts).
 */
import type { Action } from "../scene/types.js";
import { restartsAt } from "./actionData.js";
import { keyframeOf, lastKeyframeRecord, restorePoint } from "./checkpoint.js";
import type { TimelineCore } from "./core.js";
import type { Keyframe } from "./keyframe.js";

/**
 * The spare before an instant's actions is taken when the newest restart point lies at least
 * max(1, live bodies / SPARE_BODIES_PER_RECORD) records back. It copies 40 bytes per body (its
 * order, properties and obstacles are the last keyframe's) and the World, some tens of
 * nanoseconds per body, while a record costs microseconds of computation to replay: at most a few
 * per cent more work for a script applying an action every that many records, and a restart
 * replays at most that many.
 */
export const SPARE_BODIES_PER_RECORD = 8;

/** Before a group of actions at a new instant (with history): keep the point before it as the
 *  spare when it is the instant of an apply at or after the horizon (core.spareAt: a recomputation
 *  for anything else keeps none), the newest restart point lies far enough back (above), every
 *  event at the instant is processed and none of its actions applied. With a copy of the World
 *  (restored by copying it: no grid to rebuild, no prediction to make). */
export function noteInstantStart(c: TimelineCore): void {
  const t = c.world.time;
  if (c.spareAt !== t) return;
  if (!c.atTimeLimit || c.groupOpen) return;
  if (c.applied > 0 && (c.acts[c.applied - 1] as Action).time >= t) return;
  const newest = Math.max(lastKeyframeRecord(c), c.spare?.record ?? 0);
  if (c.records.length - newest < Math.max(1, c.live.size / SPARE_BODIES_PER_RECORD)) return;
  c.spare = { ...keyframeOf(c, false), world: c.world.clone() };
}

/** Whether the spare is a restart point for a first change `d` at time `cut` (see the header) that
 *  lies after keyframe `k` (the best of the list). */
export function spareFits(c: TimelineCore, d: number, cut: number, k: number): boolean {
  const s = c.spare;
  return s !== null && s.record >= (c.keyframes[k] as Keyframe).record && restartsAt(s, d, cut, c.acts);
}

/** Where the spare goes in the keyframe list: after every keyframe before its record. */
export function spareSlot(c: TimelineCore): number {
  const s = c.spare as Keyframe;
  const kfs = c.keyframes;
  let p = kfs.length;
  while (p > 0 && (kfs[p - 1] as Keyframe).record >= s.record) p--;
  return p;
}

/** Cut the history back to the spare. A copy of it without its World joins the list (the keyframe
 *  the readers need after the actions applied before it; a group going on there replaces it), and
 *  it stays the spare, World and all, for the next edit there: one without a World (rebuilt from
 *  its motions) keeps a copy of the one rebuilt, so that the edits after the first there (an
 *  editor's drag: one per frame) copy it instead of rebuilding it. */
export function restoreSpare(c: TimelineCore): void {
  const s = c.spare as Keyframe;
  restorePoint(c, s, spareSlot(c));
  const { world: _, ...entry } = s;
  c.keyframes.push(entry);
  if (s.world === undefined) c.spare = { ...s, world: c.world.clone() };
}
