/**
 * bodyPath: a body's whole path over [from, to] as the exact motions it followed (Timeline.path).
 *
 * Contract: the pieces are in time order, each a BodyMotion (the motion as the World stores it:
 * p(t) = positionAt(t0, x0, vx, ax, min(t, tStop)), the same for y) with the span [from, until] over
 * which the body followed it. Evaluated there, a piece gives the same numbers as stateAt, bit for bit.
 * A piece ends where the body's motion changed: a collision or stop of that body, an action that
 * restarted it (an updateBody, giveVelocity, setGlobal, removeBody), or `to`. Pieces of no length
 * (several events of the body at one instant: a Newton's cradle's chain) are left out; so the next
 * piece's start can lie elsewhere than the last piece's end only where an action moved the body
 * (updateBody x, y) or removed and added it again. Spans where the body does not exist give no piece.
 * At `to` itself a piece shows the body just before the actions logged at `to` (stateAt(to) shows it
 * after them): a move or an addition at `to` begins no piece, having no length yet.
 * A span of no length (from = to = T) gives the one point where the body is at T: a single piece
 * with from = until = T and the motion it follows from T on, after everything logged at T (the
 * collisions and the actions: stateAt(T)'s numbers at T, bit for bit), or none when the body does
 * not exist then (not yet added, or removed at T).
 *
 * Cost: one pass over the records from the last keyframe at or before `from` to `to`, touching only
 * the records of that body and the keyframes taken after actions (no other body is replayed); a
 * keyframe that is a delta of the one before (keyframeDelta.ts) is read for this body alone (its
 * added, removed and own rows), not loaded whole: a history built one action per instant holds one
 * per instant.
 */
import type { BodyMotion } from "../sim/types.js";
import type { TimelineCore } from "./core.js";
import {
  type Keyframe,
  type KeyframeDelta,
  keyframeAtOrBefore,
  liveNumber,
  loadMotions,
} from "./keyframe.js";
import { loadOwnRow, rowOf } from "./keyframeChain.js";
import { MotionTable, STRIDE } from "./motionTable.js";
import { K_ACTION, K_BODY_BODY } from "./records.js";
import { applyRecord } from "./replay.js";

/**
 * One piece of a body's path (Timeline.path): over [from, until] the body follows the motion
 * (t0, x0, y0, vx, vy, ax, ay, tStop) exactly, as `World.motion` reports one: the position at t is
 * `positionAt(t0, x0, vx, ax, min(t, tStop))` and the same with y0, vy, ay (`positionAt` is exported);
 * t0 <= from, and the body rests from tStop on.
 */
export interface PathPiece extends BodyMotion {
  /** Start of the span this motion covers (absolute time). */
  from: number;
  /** End of that span (absolute time; > from, except in the one piece of a span of no length,
   *  from = to, where until = from). */
  until: number;
}

/** Body n's motion in `table` over [from, until]. */
function pieceOf(table: MotionTable, n: number, from: number, until: number): PathPiece {
  const d = table.data;
  const o = n * STRIDE;
  return {
    from,
    until,
    t0: d[o] as number,
    x0: d[o + 1] as number,
    y0: d[o + 2] as number,
    vx: d[o + 3] as number,
    vy: d[o + 4] as number,
    ax: d[o + 5] as number,
    ay: d[o + 6] as number,
    tStop: d[o + 7] as number,
  };
}

/** Whether body n's motion row equals `row` (8 numbers: t0 … tEnd), bit for bit (NaN never occurs). */
function sameMotion(table: MotionTable, n: number, row: Float64Array): boolean {
  const d = table.data;
  const o = n * STRIDE;
  for (let k = 0; k < 8; k++) if (!Object.is(d[o + k], row[k])) return false;
  return true;
}

/**
 * What delta keyframe `kf` says of body `id`, numbered n (null: not live) at the keyframe before
 * it: its number after (removed: null; added: the new number) and its row in kf's own delta (-1:
 * none, so its motion is unchanged), or null when the delta cannot say (a body added without a row
 * never occurs: loading the whole keyframe then answers).
 */
function ownChange(
  kf: Keyframe,
  ids: readonly string[],
  id: string,
  n: number | null,
): { after: number | null; row: number } | null {
  const { added, removed } = kf.delta as KeyframeDelta;
  let after = n !== null && removed.includes(n) ? null : n;
  if (after === null) for (const m of added) if (ids[m] === id) after = m;
  const row = after === null ? -1 : rowOf(kf, after);
  return after !== null && after !== n && row < 0 ? null : { after, row };
}

/** @internal The pieces of body `id` over [from, to] (historyStart <= from <= to <= horizon), with
 *  history. Left out of the shipped types, as headlessBodyPath is: they are Timeline.path's
 *  machinery, and their TimelineCore would bring its Maps into a consumer's compiler. */
export function bodyPath(core: TimelineCore, id: string, from: number, to: number): PathPiece[] {
  const kfs = core.keyframes;
  const rec = core.records;
  let k = Math.max(0, keyframeAtOrBefore(kfs, from));
  let kf = kfs[k] as Keyframe;
  const table = new MotionTable(Math.max(16, kf.bodyCount));
  loadMotions(kf, table, core.chains);
  let n = liveNumber(kf, core.bodyIds, id, core.chains);
  let start = from;
  const saved = new Float64Array(8);
  const out: PathPiece[] = [];
  const close = (t: number) => {
    if (n !== null && t > start) out.push(pieceOf(table, n, start, t));
  };
  // The keyframes taken at record i: after a group of actions, the motions the actions left (a
  // periodic keyframe holds what the replay holds, and this body's records are all replayed).
  const keyframesAt = (i: number) => {
    while (
      k + 1 < kfs.length &&
      (kfs[k + 1] as Keyframe).record === i &&
      (kfs[k + 1] as Keyframe).time <= to
    ) {
      const prev = kfs[k] as Keyframe;
      kf = kfs[++k] as Keyframe;
      if (!kf.afterActions) continue;
      // a delta of the keyframe before (whose motion of this body the table holds): its own rows
      const own = kf.delta?.prev === prev ? ownChange(kf, core.bodyIds, id, n) : null;
      if (own !== null && own.after === n && own.row < 0) continue; // not touched
      if (n !== null) saved.set(table.data.subarray(n * STRIDE, n * STRIDE + 8));
      const before = n;
      const load = () =>
        own === null ? loadMotions(kf, table, core.chains) : loadOwnRow(kf, own.row, table);
      table.ensure(kf.bodyCount);
      load();
      const after = own === null ? liveNumber(kf, core.bodyIds, id, core.chains) : own.after;
      if (after === before && after !== null && sameMotion(table, after, saved)) continue;
      if (before !== null) {
        // close with the motion it had: put it back for a moment
        table.data.set(saved, before * STRIDE);
        close(kf.time);
        if (after !== null) load();
      }
      n = after;
      start = Math.max(kf.time, from);
    }
  };
  for (let i = kf.record; i < rec.length; i++) {
    // (a group of actions at or before `to` may be followed by a record after it)
    keyframesAt(i);
    const t = rec.time[i] as number;
    if (t > to) break;
    if (n === null || rec.kind[i] === K_ACTION) continue;
    if (rec.a[i] !== n && !(rec.kind[i] === K_BODY_BODY && rec.b[i] === n)) continue;
    close(t);
    applyRecord(rec, i, table, kf);
    start = Math.max(t, from);
  }
  keyframesAt(rec.length); // (the keyframes after the loop's last record, up to `to`)
  // a span of no length: the motion everything logged at `to` left (all of it replayed above)
  if (to === from) return n === null ? [] : [pieceOf(table, n, from, to)];
  close(to);
  return out;
}

/** @internal The pieces of body `id` over [from, to] of a timeline without history: only its
 *  current motion (the span since the last logged entry; the caller checked lastLogged <= from <=
 *  to); a span of no length gives that motion too, as one piece from = until. */
export function headlessBodyPath(core: TimelineCore, id: string, from: number, to: number): PathPiece[] {
  const w = core.world;
  if (!w.hasBody(id)) return [];
  return [{ from, until: to, ...w.motion(id) }];
}
