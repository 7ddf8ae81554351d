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
 */
import type { TimelineCore } from "./core.js";
import { type Keyframe, keyframeAtRecord, loadMotions } from "./keyframe.js";
import { MotionTable } from "./motionTable.js";
import { K_ACTION } from "./records.js";
import { applyRecord, describe } from "./replay.js";
import type { LogEvent } from "./types.js";

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
    const kfs = core.keyframes;
    const start = Math.max(0, keyframeAtRecord(kfs, from));
    if (!this.canContinue(core, from, (kfs[start] as Keyframe).record)) {
      this.core = core;
      this.rewrites = core.rewrites;
      this.k = start;
      this.next = (kfs[start] as Keyframe).record;
      loadMotions(kfs[start] as Keyframe, this.table);
    }
    const rec = core.records;
    const table = this.table;
    let k = this.k;
    let kf = kfs[k] as Keyframe;
    for (let i = this.next; i < to; i++) {
      while (k + 1 < kfs.length && (kfs[k + 1] as Keyframe).record === i) {
        k++;
        kf = kfs[k] as Keyframe;
        loadMotions(kf, table);
      }
      if (i >= from) out.push(describe(core, i, table, kf));
      if (rec.kind[i] !== K_ACTION) applyRecord(rec, i, table, kf);
    }
    this.replayed += to - this.next;
    this.k = k;
    this.next = to;
    return out;
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
