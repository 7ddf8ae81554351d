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
 * - loadDelta(kf, table): a keyframe's motions, its chain's full keyframe loaded and each delta's rows
 *   after it, the same numbers the full keyframe of that point gives (each row is loaded as a full
 *   keyframe loads it).
 * - orderOf(kf, ids), arraysOf(kf, ids): the live order, and the full keyframe's arrays, of any
 *   keyframe (the last one asked for kept: a reader asks the same keyframe again and again).
 */
import type { Action } from "../scene/types.js";
import type { TimelineCore } from "./core.js";
import type { Keyframe, KeyframeArrays, KeyframeDelta } from "./keyframe.js";
import { MotionTable, STRIDE } from "./motionTable.js";
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

/** The chain of `kf` from its full keyframe on (full first). */
function chainOf(kf: Keyframe): Keyframe[] {
  const chain = [kf];
  for (let k = kf; k.delta !== null; k = k.delta.prev) chain.push(k.delta.prev);
  return chain.reverse();
}

/** Load a delta keyframe's motions into `table` (see the header; loadFull loads a full one). */
export function loadDelta(kf: Keyframe, table: MotionTable, loadFull: (k: Keyframe) => void): void {
  const chain = chainOf(kf);
  loadFull(chain[0] as Keyframe);
  table.ensure(kf.bodyCount);
  const [gx, gy] = kf.gravity;
  for (let c = 1; c < chain.length; c++) {
    const { nums, rows } = (chain[c] as Keyframe).delta as KeyframeDelta;
    for (let k = 0; k < nums.length; k++) {
      const n = nums[k] as number;
      const q = k * DELTA_ROW;
      table.setProps(n, rows[q + 5] as number, rows[q + 6] as number, rows[q + 7] as number);
      const r = (j: number) => rows[q + j] as number;
      table.start(n, r(0), r(1), r(2), r(3), r(4), kf.g, gx, gy);
    }
  }
}

/** The last keyframe whose order or arrays were asked for, and them. */
let cached: { kf: Keyframe | null; order: Uint32Array; arrays: KeyframeArrays | null } = {
  kf: null,
  order: new Uint32Array(0),
  arrays: null,
};

/** Live body numbers of `kf` sorted by id (`ids[n]` names body n, as for worldAt). */
export function orderOf(kf: Keyframe, ids: readonly string[]): Uint32Array {
  if (kf.full !== null) return kf.full.order;
  if (cached.kf === kf) return cached.order;
  const chain = chainOf(kf);
  const added: number[] = [];
  const removed = new Set<number>();
  for (let c = 1; c < chain.length; c++) {
    const d = (chain[c] as Keyframe).delta as KeyframeDelta;
    for (const n of d.added) added.push(n);
    for (const n of d.removed) removed.add(n);
  }
  // a body one delta added and a later one removed is in the first's `added` and the later's `removed`
  const base = ((chain[0] as Keyframe).full as KeyframeArrays).order;
  const kept = removed.size === 0 ? base : base.filter((n) => !removed.has(n));
  const order = mergeById(kept, removed.size === 0 ? added : added.filter((n) => !removed.has(n)), ids);
  cached = { kf, order, arrays: null };
  return order;
}

/** The arrays a full keyframe of `kf`'s point holds (see the header). */
export function arraysOf(
  kf: Keyframe,
  ids: readonly string[],
  load: (k: Keyframe, t: MotionTable) => void,
): KeyframeArrays {
  if (kf.full !== null) return kf.full;
  if (cached.kf === kf && cached.arrays !== null) return cached.arrays;
  const order = orderOf(kf, ids);
  const table = new MotionTable(Math.max(16, kf.bodyCount));
  load(kf, table);
  const motions = new Float64Array(order.length * 5);
  const props = new Float64Array(order.length * 3);
  const d = table.data;
  order.forEach((n, k) => {
    const o = n * STRIDE;
    for (let j = 0; j < 5; j++) motions[5 * k + j] = d[o + j] as number;
    for (let j = 0; j < 3; j++) props[3 * k + j] = d[o + 8 + j] as number;
  });
  const arrays = { order, props, motions };
  cached = { kf, order, arrays };
  return arrays;
}
