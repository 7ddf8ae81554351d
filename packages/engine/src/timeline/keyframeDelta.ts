/**
 * Keyframes taken after a group of actions as a delta of the keyframe before them (keyframe.ts,
 * Keyframe.delta): the motions of the bodies the records since then touched (an event's bodies, an
 * action's body, the bodies added), the bodies added and the bodies removed, not every body. A scene
 * built one action per instant (an editor adding discs at different times, a game spawning a body
 * every frame and removing old ones) took a copy of every body per instant: 4,000 discs one per
 * instant spent seconds in keyframes.
 * Keyframes stay one per instant (not one per amount of work done): stateAt's replay, the log and
 * path readers, forgetBefore's cut, an edit's restart and the spare restart point stand on them, and
 * a delta keeps each where it was, so nothing observable moves.
 *
 * - deltaSince(core, prev): the delta of the core's current point over keyframe `prev`, or null when
 *   a full keyframe is due: an action since prev that changes an obstacle or the globals (the
 *   obstacle lists shared with prev would change), or the chain back to the last full keyframe
 *   would hold more rows than half the live bodies: loading a keyframe then costs at most about 1.5
 *   full loads, and its order a sort of at most that many ids (stateAt stays bounded; a scene built
 *   in one group, fromScene's, gets a full keyframe: its reads sort nothing). A removed body's
 *   number is in its action's record (actionGroup.ts).
 * Reading a delta (its motions, its order, the arrays a full keyframe would hold): keyframeChain.ts.
 */
import type { Action } from "../scene/types.js";
import type { TimelineCore } from "./core.js";
import type { Keyframe, KeyframeDelta } from "./keyframe.js";
import { STRIDE } from "./motionTable.js";
import { K_ACTION, K_BODY_BODY } from "./records.js";

/** Numbers per row of a delta: t0, x0, y0, vx0, vy0, r, m, mu. */
export const DELTA_ROW = 8;

/** The body numbers of `sorted` (sorted by id) and `added` (none of them in it) sorted by id
 *  (`ids[n]` names body n; ids differ), as a new array. */
export function mergeById(
  sorted: Uint32Array,
  added: readonly number[],
  ids: readonly string[],
): Uint32Array {
  const id = (n: number) => ids[n] as string;
  const extra = added.slice().sort((p, q) => (id(p) < id(q) ? -1 : 1));
  const out = new Uint32Array(sorted.length + extra.length);
  let i = 0;
  let j = 0;
  for (let k = 0; k < out.length; k++) {
    const a = sorted[i];
    const b = extra[j];
    if (b === undefined || (a !== undefined && id(a) < id(b))) {
      out[k] = a as number;
      i++;
    } else {
      out[k] = b;
      j++;
    }
  }
  return out;
}

/** Whether an action leaves the keyframe's obstacles and globals as they were. */
function deltaAction(a: Action): boolean {
  return (
    a.type === "addBody" || a.type === "giveVelocity" || a.type === "updateBody" || a.type === "removeBody"
  );
}

/** The delta of the core's current point over `prev` (see the header), or null. */
export function deltaSince(c: TimelineCore, prev: Keyframe): KeyframeDelta | null {
  const rec = c.records;
  const touched = new Set<number>();
  const removed: number[] = [];
  for (let i = prev.record; i < rec.length; i++) {
    const kind = rec.kind[i] as number;
    if (kind === K_ACTION) {
      const a = c.acts[rec.a[i] as number] as Action;
      if (!deltaAction(a)) return null;
      if (a.type === "removeBody") {
        if ((rec.b[i] as number) < prev.bodyCount) removed.push(rec.b[i] as number);
      } else touched.add(c.live.get((a as { id: string }).id) as number);
    } else {
      touched.add(rec.a[i] as number);
      if (kind === K_BODY_BODY) touched.add(rec.b[i] as number);
    }
  }
  // the rows of the bodies live now (one touched, then removed, has none; undefined: an action's
  // body removed since)
  const live = (n: number | undefined): n is number =>
    n !== undefined && c.live.get(c.bodyIds[n] as string) === n;
  const nums = Uint32Array.from([...touched].filter(live));
  const chainRows = (prev.delta?.chainRows ?? 0) + nums.length + removed.length;
  if (2 * chainRows > c.live.size) return null;
  const rows = new Float64Array(nums.length * DELTA_ROW);
  const d = c.table.data;
  nums.forEach((n, k) => {
    const o = n * STRIDE;
    const q = k * DELTA_ROW;
    for (let j = 0; j < 5; j++) rows[q + j] = d[o + j] as number;
    rows[q + 5] = d[o + 8] as number;
    rows[q + 6] = d[o + 9] as number;
    rows[q + 7] = d[o + 10] as number;
  });
  const added: number[] = [];
  for (let n = prev.bodyCount; n < c.bodyIds.length; n++) if (live(n)) added.push(n);
  return {
    prev,
    nums,
    rows,
    added: mergeById(new Uint32Array(0), added, c.bodyIds),
    removed: Uint32Array.from(removed),
    chainRows,
  };
}
