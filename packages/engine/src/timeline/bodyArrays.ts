/**
 * Timeline.bodyArraysAt: every body at time t as arrays (sim/bodyArrays.ts: BodyArrays and the
 * reuse of `into`), written from the motions at t the way stateAt finds them (replay.ts: the last
 * keyframe at or before t, then the records up to t) but without a BodyState per body: the same
 * bodies in the same order (the keyframe's `order`, by id) and the same numbers bit for bit (the
 * MotionTable's evaluation, motionTable.ts). Without history, from the World (World.bodyArrays).
 *
 * ArraysCursor keeps its own replay between reads (a MotionCursor, motionCursor.ts), as logCursor.ts
 * does for the log: a read at a later t (playback, a scrub forwards) goes on from where the last
 * read stopped, replaying only the records in between (and across keyframes that are deltas, loading
 * only their rows) instead of loading the keyframe and replaying everything since; it starts again
 * from the keyframe when that cannot give the same motions. Both ways agree bit for bit.
 */
import { arraysFor, type BodyArrays, writeMotionAt } from "../sim/bodyArrays.js";
import type { TimelineCore } from "./core.js";
import { MotionCursor } from "./motionCursor.js";
import { STRIDE } from "./motionTable.js";
import { requireHeadlessTime } from "./replay.js";

export class ArraysCursor {
  private readonly motions = new MotionCursor();

  /** The bodies at time t (a time stateAt accepts, already checked) into `into` or new arrays. */
  read(core: TimelineCore, t: number, into: BodyArrays | undefined): BodyArrays {
    if (!core.history) {
      requireHeadlessTime(core, t, "bodyArraysAt");
      return core.world.bodyArrays(t, into);
    }
    const order = core.chains.orderOf(this.motions.seek(core, t), core.bodyIds);
    const names = core.bodyIds;
    const n = order.length;
    const idAt = (k: number) => names[order[k] as number] as string;
    const out = arraysFor(t, n, idAt, () => Array.from(order, (i) => names[i] as string), into);
    const { r, m, mu } = out;
    const d = this.motions.table.data;
    for (let k = 0; k < n; k++) {
      const o = (order[k] as number) * STRIDE;
      writeMotionAt(out, k, d, o, t);
      r[k] = d[o + 8] as number;
      m[k] = d[o + 9] as number;
      mu[k] = d[o + 10] as number;
    }
    return out;
  }
}
