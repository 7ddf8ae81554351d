/**
 * Timeline.bodyArraysAt: every body at time t as arrays (sim/bodyArrays.ts: BodyArrays and the
 * reuse of `into`), written from the motions at t the way stateAt finds them (replay.ts: the last
 * keyframe at or before t, then the records up to t) but without a BodyState per body: the same
 * bodies in the same order (the keyframe's `order`, by id) and the same numbers bit for bit (the
 * MotionTable's evaluation, motionTable.ts). Without history, from the World (World.bodyArrays).
 *
 * ArraysCursor keeps its own replay between reads, as logCursor.ts does for the log: a read at a
 * later t (playback, a scrub forwards) that a fresh replay would start from the same keyframe goes
 * on from where the last read stopped, replaying only the records in between instead of loading
 * the keyframe and replaying everything since. It starts again from the keyframe when that cannot
 * give the same motions: another core or keyframe, a record already replayed that lies after t,
 * or a rewrite of records or keyframes (`core.rewrites`: cuts, restores, forgetBefore). Replaying a
 * record is the same arithmetic whether or not the replay paused before it, so both ways agree bit
 * for bit.
 */
import { arraysFor, type BodyArrays, writeMotionAt } from "../sim/bodyArrays.js";
import type { TimelineCore } from "./core.js";
import { type Keyframe, keyframeAtOrBefore, loadMotions } from "./keyframe.js";
import { orderOf } from "./keyframeChain.js";
import { MotionTable, STRIDE } from "./motionTable.js";
import { K_ACTION } from "./records.js";
import { applyRecord, requireHeadlessTime } from "./replay.js";

export class ArraysCursor {
  private core: TimelineCore | null = null;
  private rewrites = -1;
  /** The keyframe loaded into `table`, whose records [kf.record, next) were replayed since. */
  private kf: Keyframe | null = null;
  private next = 0;
  private readonly table = new MotionTable();

  /** The bodies at time t (a time stateAt accepts, already checked) into `into` or new arrays. */
  read(core: TimelineCore, t: number, into: BodyArrays | undefined): BodyArrays {
    if (!core.history) {
      requireHeadlessTime(core, t, "bodyArraysAt");
      return core.world.bodyArrays(t, into);
    }
    const order = orderOf(this.seek(core, t), core.bodyIds);
    const names = core.bodyIds;
    const n = order.length;
    const idAt = (k: number) => names[order[k] as number] as string;
    const out = arraysFor(t, n, idAt, () => Array.from(order, (i) => names[i] as string), into);
    const { r, m, mu } = out;
    const d = this.table.data;
    for (let k = 0; k < n; k++) {
      const o = (order[k] as number) * STRIDE;
      writeMotionAt(out, k, d, o, t);
      r[k] = d[o + 8] as number;
      m[k] = d[o + 9] as number;
      mu[k] = d[o + 10] as number;
    }
    return out;
  }

  /** Make `table` hold the motions at t exactly as replay.ts's replayTo would; returns the keyframe. */
  private seek(core: TimelineCore, t: number): Keyframe {
    const kfs = core.keyframes;
    const kf = kfs[Math.max(0, keyframeAtOrBefore(kfs, t))] as Keyframe;
    const rec = core.records;
    const replayedUpToT = this.next === kf.record || (rec.time[this.next - 1] as number) <= t;
    if (!(this.core === core && this.rewrites === core.rewrites && this.kf === kf && replayedUpToT)) {
      this.core = core;
      this.rewrites = core.rewrites;
      this.kf = kf;
      this.next = kf.record;
      loadMotions(kf, this.table);
    }
    let i = this.next;
    for (; i < rec.length && (rec.time[i] as number) <= t; i++) {
      if (rec.kind[i] === K_ACTION) break; // as in replayTo: a keyframe follows every action group
      applyRecord(rec, i, this.table, kf);
    }
    this.next = i;
    return kf;
  }
}
