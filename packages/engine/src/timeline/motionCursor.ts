/**
 * MotionCursor: the motions of every body at a time t of the history, as stateAt finds them (the
 * last keyframe at or before t loaded, then the records up to t replayed: replay.ts), kept between
 * reads so that a read at a later time goes on from the last one instead of starting again (the
 * reader's stateAt and bodyArraysAt each hold one: bodyArrays.ts).
 *
 * Going on: from the same keyframe, the records between the last read and t are replayed (a read
 * whose records were replayed past t starts again). Across keyframes, when every keyframe between
 * the cursor's and t's is a delta of the one before it (keyframeDelta.ts), each delta's own rows are
 * loaded over the table (patchDelta): a delta has a row for every body a record since its `prev`
 * touched (and every body its actions added or changed), so the rows the replay left and the ones
 * it did not reach are all overwritten, and every other body holds what its `prev` held: the table
 * is then exactly the delta keyframe's load. A scrub forwards over a history built one action per
 * instant (a keyframe per instant) loads a few rows per instant crossed, not every body: while the
 * rows crossed stay under CROSS_ROWS_PER_BODY × the keyframe's bodies (else a fresh load is
 * cheaper). It starts again from the keyframe for another core, a rewrite of records or keyframes
 * (`core.rewrites`: cuts, restores, forgetBefore), or an earlier t.
 * Replaying a record and loading a row are the same arithmetic whichever way the table got there,
 * so every way gives the same numbers bit for bit.
 */
import type { TimelineCore } from "./core.js";
import { type Keyframe, keyframeAtOrBefore, loadMotions } from "./keyframe.js";
import { patchDelta } from "./keyframeChain.js";
import { MotionTable } from "./motionTable.js";
import { K_ACTION } from "./records.js";
import { applyRecord } from "./replay.js";

/** Rows crossed going on over deltas, per body of the target keyframe, above which a fresh load
 *  (a full keyframe and its chain's rows, about one to 1.5 loads per body) is done instead. */
const CROSS_ROWS_PER_BODY = 0.5;

export class MotionCursor {
  private core: TimelineCore | null = null;
  private rewrites = -1;
  /** The keyframe loaded into `table` (keyframes[k]), whose records [kf.record, next) were replayed. */
  private kf: Keyframe | null = null;
  private k = -1;
  private next = 0;
  readonly table = new MotionTable();

  /** Make `table` hold the motions at t (a time the reader accepts, with history); returns the
   *  keyframe they start from (its order is the bodies'). */
  seek(core: TimelineCore, t: number): Keyframe {
    const kfs = core.keyframes;
    const at = Math.max(0, keyframeAtOrBefore(kfs, t));
    const kf = kfs[at] as Keyframe;
    const rec = core.records;
    const same = this.core === core && this.rewrites === core.rewrites && kfs[this.k] === this.kf;
    if (same && this.k === at && (this.next === kf.record || (rec.time[this.next - 1] as number) <= t)) {
      // the same keyframe, replayed up to t at most: go on
    } else if (same && this.k < at && this.canCross(kfs, at)) {
      for (let j = this.k + 1; j <= at; j++) patchDelta(kfs[j] as Keyframe, this.table);
      this.next = kf.record;
    } else {
      this.core = core;
      this.rewrites = core.rewrites;
      this.next = kf.record;
      loadMotions(kf, this.table, core.chains);
    }
    this.k = at;
    this.kf = kf;
    let i = this.next;
    for (; i < rec.length && (rec.time[i] as number) <= t; i++) {
      if (rec.kind[i] === K_ACTION) break; // a keyframe follows every action group
      applyRecord(rec, i, this.table, kf);
    }
    this.next = i;
    return kf;
  }

  /** Whether keyframes k+1 … at are deltas, each of the one before, with few enough rows. */
  private canCross(kfs: readonly Keyframe[], at: number): boolean {
    const budget = CROSS_ROWS_PER_BODY * (kfs[at] as Keyframe).bodyCount;
    let rows = 0;
    for (let j = this.k + 1; j <= at; j++) {
      const delta = (kfs[j] as Keyframe).delta;
      if (delta === null || delta.prev !== kfs[j - 1]) return false;
      rows += delta.nums.length + 1;
      if (rows > budget) return false;
    }
    return true;
  }
}
