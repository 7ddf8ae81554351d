/**
 * LogCursor: reads the event log of a TimelineCore and remembers where its replay stopped, so a
 * reader that walks the log in order (`event(i)`, `event(i + 1)`, … or consecutive `eventRange`
 * blocks) replays each record once, instead of replaying from the keyframe before i on every call.
 *
 * Contract: `read(core, from, to)` returns exactly what a fresh replay from the last keyframe at or
 * before `from` gives (the same LogEvents, bit for bit). The cursor continues from its position only
 * when that position lies in [last keyframe at or before `from`, `from`] of the same core, and no
 * record or keyframe has been rewritten since (`core.rewrites`: cuts, restores and replaced keyframes;
 * appends keep the replayed prefix valid). Otherwise it starts again from the keyframe.
 * `detail(core, i)` is the same walk for one entry, with its bodies' states just before it (the
 * motions the replay holds there) and just after it (eventDetail.ts).
 */
import type { TimelineCore } from "./core.js";
import { detailOf } from "./eventDetail.js";
import { type Keyframe, keyframeAtRecord, loadMotions } from "./keyframe.js";
import { patchDelta } from "./keyframeChain.js";
import { MotionTable } from "./motionTable.js";
import { K_ACTION } from "./records.js";
import { applyRecord, describe } from "./replay.js";
import type { EventDetail, LogEvent } from "./types.js";

export class LogCursor {
  private core: TimelineCore | null = null;
  private rewrites = -1;
  /** Index of the keyframe last loaded into `table`. */
  private k = 0;
  /** `table` holds the motions just before record `next`. */
  private next = 0;
  private readonly table = new MotionTable();
  /** Records replayed so far (keyframe loads excluded): what a walk costs, for tests. */
  replayed = 0;

  /** Log events of records [from, to), to <= records.length, in order. */
  read(core: TimelineCore, from: number, to: number): LogEvent[] {
    const out: LogEvent[] = [];
    if (from >= to) return out;
    this.seek(core, from);
    while (this.next < to) {
      out.push(describe(core, this.next, this.table, this.sync(core)));
      this.step(core);
    }
    return out;
  }

  /** Log event of record i (< records.length) with its bodies' states just before and after it. */
  detail(core: TimelineCore, i: number): EventDetail {
    this.seek(core, i);
    return detailOf(core, i, this.table, this.sync(core), () => this.step(core));
  }

  /** Make `table` hold the motions just before record `from`: go on from the cursor's position when
   *  it can serve (canContinue), else start again from the last keyframe at or before it. */
  private seek(core: TimelineCore, from: number): void {
    const kfs = core.keyframes;
    const start = Math.max(0, keyframeAtRecord(kfs, from));
    if (!this.canContinue(core, from, (kfs[start] as Keyframe).record)) {
      this.core = core;
      this.rewrites = core.rewrites;
      this.k = start;
      this.next = (kfs[start] as Keyframe).record;
      loadMotions(kfs[start] as Keyframe, this.table, core.chains);
    }
    while (this.next < from) this.step(core);
  }

  /** Load the keyframes taken at record `next` (they replace the motions); the one in force there. */
  private sync(core: TimelineCore): Keyframe {
    const kfs = core.keyframes;
    while (this.k + 1 < kfs.length && (kfs[this.k + 1] as Keyframe).record === this.next) {
      const kf = kfs[++this.k] as Keyframe;
      // a delta of the keyframe the table holds (replayed since): its own rows (motionCursor.ts)
      if (kf.delta?.prev === kfs[this.k - 1]) patchDelta(kf, this.table);
      else loadMotions(kf, this.table, core.chains);
    }
    return kfs[this.k] as Keyframe;
  }

  /** Replay record `next` (an action changes no motion here: the keyframe after its group does). */
  private step(core: TimelineCore): void {
    const kf = this.sync(core);
    const i = this.next;
    if (core.records.kind[i] !== K_ACTION) applyRecord(core.records, i, this.table, kf);
    this.next = i + 1;
    this.replayed++;
  }

  /** Whether the remembered position can serve a read from `from`: same core, nothing rewritten,
   *  and the position between the keyframe a fresh read would load (at record `kfRecord`) and `from`. */
  private canContinue(core: TimelineCore, from: number, kfRecord: number): boolean {
    return (
      this.core === core &&
      this.rewrites === core.rewrites &&
      this.next <= from &&
      this.next >= kfRecord &&
      this.next <= core.records.length
    );
  }
}
