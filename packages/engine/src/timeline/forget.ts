/**
 * forgetBefore(core, t): drops the start of a TimelineCore's history (Timeline.forgetBefore), for a
 * game or a long replay that keeps only its recent past. Keyframes are the only restart points, so
 * the history is cut at the last keyframe at or before t: that keyframe becomes keyframes[0] (the
 * start of the kept history, `historyStart` = its time), the records before it are dropped
 * (Records.dropBefore: moved to the front, the arrays shrunk when mostly empty) and the keyframes
 * after it have their record indices shifted to the kept records. Everything a read at a time >= its
 * time needs is kept, so those reads (and edits there, restarting from keyframes[0] at worst) give
 * exactly what they gave before.
 *
 * What stays: the actions (small; `toScene` still writes the whole scene), and per action its event
 * total (goals.ts) and, for an addBody, the body's id in the registry: about 100 to 300 bytes per
 * action (200 measured for a giveVelocity), which a game applying one action a frame still
 * accumulates (60 actions a second: some 12 KB a second, against megabytes for the history).
 * Totals (counts, eventTotal, the log's global entry numbers) are unchanged: core.forgotten.records
 * says how many log entries were dropped. The core's chain caches (keyframeChain.ts) are emptied:
 * they know the replaced keyframe objects only, and would keep the forgotten ones reachable.
 * What the kept history refuses (reads before it, edits that would change it): kept.ts.
 */
import { given } from "../sim/refusalText.js";
import type { TimelineCore } from "./core.js";
import { type Keyframe, keyframeAtOrBefore, loadMotions } from "./keyframe.js";

/** Start of the kept history: keyframes[0]'s time (0 until something is forgotten, and without
 *  history). */
export function historyStart(c: TimelineCore): number {
  return c.history ? (c.keyframes[0] as Keyframe).time : 0;
}

/** forgetBefore's t: a number in [0, horizon]; else a RangeError naming the method and the bounds. */
export function forgetTime(t: unknown, horizon: number): number {
  if (typeof t !== "number" || !(t >= 0 && t <= horizon))
    throw new RangeError(
      `forgetBefore(t): must be a number in [0, ${horizon}], the computed history (got ${given(t)})`,
    );
  return t === 0 ? 0 : t;
}

/**
 * Forget the history before the last keyframe at or before t (t checked by the caller, in [0,
 * horizon]). Returns the start of the kept history and whether anything was dropped. Without
 * history nothing is kept, so nothing changes; the horizon is returned.
 */
export function forgetBefore(c: TimelineCore, t: number): { start: number; dropped: boolean } {
  if (!c.history) return { start: c.horizon, dropped: false };
  const kfs = c.keyframes;
  const k = keyframeAtOrBefore(kfs, t);
  // k <= 0: t before the second keyframe (or before the kept start): nothing more to forget
  if (k <= 0) return { start: historyStart(c), dropped: false };
  const cut = kfs[k] as Keyframe;
  const n = cut.record;
  const r = c.records;
  if (n > 0) {
    c.forgotten.lastTime = r.time[n - 1] as number;
    c.forgotten.lastKind = r.kind[n - 1] as number;
  }
  r.dropBefore(n);
  c.forgotten.records += n;
  // new objects (the keyframes are not shared outside the core, but an object never changes); a
  // delta (keyframeDelta.ts) patches the new object of the keyframe before it, or holds its bodies
  // in full when that one goes (keyframes[0]: nothing before it is kept)
  const moved = new Map<Keyframe, Keyframe>();
  const move = (kf: Keyframe): Keyframe => {
    const copy: Keyframe = { ...kf, record: kf.record - n };
    const prev = kf.delta === null ? undefined : moved.get(kf.delta.prev);
    if (kf.delta !== null && prev === undefined) {
      copy.full = c.chains.arraysOf(kf, c.bodyIds, (k, t) => loadMotions(k, t, c.chains));
      copy.delta = null;
    } else if (kf.delta !== null) copy.delta = { ...kf.delta, prev: prev as Keyframe };
    moved.set(kf, copy);
    return copy;
  };
  c.keyframes = kfs.slice(k).map(move);
  // the spare restart point (restartPoint.ts) moves with the records, or goes with them
  c.spare = c.spare !== null && c.spare.record > n ? move(c.spare) : null;
  // a log cursor's replay position (logCursor.ts) names records by their old index: it restarts
  c.rewrites++;
  // the chain caches know the old keyframe objects only: they could never hit again (keyframeChain.ts)
  c.chains.clear();
  return { start: cut.time, dropped: true };
}
