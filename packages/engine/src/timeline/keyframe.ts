/**
 * Keyframes of a Timeline: the state of all bodies' motions at one point of the computation, taken
 * after every group of actions and every K records (K grows with the number of bodies so keyframes
 * cost a bounded number of bytes per event). Every keyframe is also a point a recomputation restarts
 * from: worldAt(kf) rebuilds the World from the motions, obstacles and globals, which gives the same
 * future bit for bit (World.restoreBodyMotion: addBodyMotion without the overlap check, since the
 * World's own motions may hold a pressed pair's overlap). stateAt(t) = the last keyframe at or
 * before t + the records up to t. A keyframe after a group of actions may be a delta of the one
 * before it (keyframeDelta.ts): read its order and arrays through the Timeline's ChainCache
 * (keyframeChain.ts: TimelineCore.chains), which every function here that may read a delta is given.
 */
import type { Vec2 } from "../scene/types.js";
import type { LineState, PointState } from "../sim/types.js";
import { World } from "../sim/world.js";
import type { ZenoCounters } from "../sim/zenoWatch.js";
import type { ChainCache } from "./keyframeChain.js";
import { type MotionTable, STRIDE } from "./motionTable.js";
import type { TimelineCounts } from "./types.js";

export interface Keyframe {
  /** simulation time of the keyframe */
  time: number;
  /** number of records before it */
  record: number;
  /** number of actions applied before it */
  actionCount: number;
  /** taken right after a group of actions, before advancing */
  afterActions: boolean;
  /** every event at `time` had been processed (the advance before it stopped at a time limit) */
  atTimeLimit: boolean;
  counts: TimelineCounts;
  /** collisions and stops processed before it */
  eventTotal: number;
  g: number;
  gravity: Vec2;
  /** the bodies of a full keyframe, null for a delta */
  full: KeyframeArrays | null;
  /** of a keyframe after a group of actions, the bodies that changed since the keyframe before it
   *  (keyframeDelta.ts) */
  delta: KeyframeDelta | null;
  lines: LineState[];
  points: PointState[];
  /** body numbers and obstacle numbers allocated so far */
  bodyCount: number;
  lineCount: number;
  pointCount: number;
  /** id → number maps of obstacles alive at the keyframe */
  lineNums: Map<string, number>;
  pointNums: Map<string, number>;
  /** the World's Zeno watch counters (World.zenoWatch), so a restart detects a Zeno state at the
   *  same event as the uninterrupted computation */
  zeno: Readonly<ZenoCounters>;
  /** A copy of the World at this point, never changed, restored by copying it (no rebuild, no
   *  predictions to recompute): only the spare restart point taken before an instant's actions
   *  holds one (restartPoint.ts). */
  world?: World;
}

/** The bodies of a full keyframe. */
export interface KeyframeArrays {
  /** live body numbers sorted by id (shared with the keyframes since the last group of actions) */
  order: Uint32Array;
  /** r, m, mu per body of `order` (shared like `order`: only actions change them) */
  props: Float64Array;
  /** t0, x0, y0, vx0, vy0 per body of `order`; ax, ay and the end time are recomputed on loading
   *  with motionLaw, exactly as the World computed them */
  motions: Float64Array;
}

/** What a keyframe after a group of actions may hold instead of KeyframeArrays (keyframeDelta.ts). */
export interface KeyframeDelta {
  /** the keyframe before it, which this one patches */
  prev: Keyframe;
  /** the body numbers that changed since prev (or are new), and per number t0, x0, y0, vx0, vy0,
   *  r, m, mu (DELTA_ROW) */
  nums: Uint32Array;
  rows: Float64Array;
  /** the body numbers added since prev (live), sorted by id, and those of prev's bodies removed */
  added: Uint32Array;
  removed: Uint32Array;
  /** rows of the deltas back to the full keyframe, this one's included */
  chainRows: number;
}

/** Numbers per body in KeyframeArrays.motions. */
const KF_MOTION = 5;

/** Copy the motion starts (t0, x0, y0, vx0, vy0) of the bodies in `order` out of `table`. */
export function snapshotMotions(table: MotionTable, order: Uint32Array): Float64Array {
  const out = new Float64Array(order.length * KF_MOTION);
  const d = table.data;
  for (let k = 0; k < order.length; k++) {
    const o = (order[k] as number) * STRIDE;
    const q = k * KF_MOTION;
    out[q] = d[o] as number;
    out[q + 1] = d[o + 1] as number;
    out[q + 2] = d[o + 2] as number;
    out[q + 3] = d[o + 3] as number;
    out[q + 4] = d[o + 4] as number;
  }
  return out;
}

/** r, m, mu of the bodies in `order`. */
export function snapshotProps(table: MotionTable, order: Uint32Array): Float64Array {
  const out = new Float64Array(order.length * 3);
  for (let k = 0; k < order.length; k++) {
    const i = order[k] as number;
    out[3 * k] = table.r(i);
    out[3 * k + 1] = table.m(i);
    out[3 * k + 2] = table.mu(i);
  }
  return out;
}

/** Number of the live body `id` in a keyframe's order (`ids[n]` names body n), or null. */
export function liveNumber(
  kf: Keyframe,
  ids: readonly string[],
  id: string,
  chains: ChainCache,
): number | null {
  for (const n of chains.orderOf(kf, ids)) if (ids[n] === id) return n;
  return null;
}

/** Load a keyframe's motions into `table` (made large enough for kf.bodyCount bodies). */
export function loadMotions(kf: Keyframe, table: MotionTable, chains: ChainCache): void {
  if (kf.full === null)
    chains.loadDelta(kf, table, (full, marks, mark) => loadFull(full, table, marks, mark));
  else loadFull(kf, table, NO_MARKS, 0);
}

const NO_MARKS = new Uint32Array(0);

/** Load a full keyframe's bodies into `table`, but those marked (marks[n] === mark, mark > 0: a
 *  delta's row loaded them already). */
function loadFull(kf: Keyframe, table: MotionTable, marks: Uint32Array, mark: number): void {
  table.ensure(kf.bodyCount);
  const { order, motions: m, props: p } = kf.full as KeyframeArrays;
  const [gx, gy] = kf.gravity;
  for (let k = 0; k < order.length; k++) {
    const n = order[k] as number;
    if (mark !== 0 && marks[n] === mark) continue;
    const q = k * KF_MOTION;
    table.setProps(n, p[3 * k] as number, p[3 * k + 1] as number, p[3 * k + 2] as number);
    table.start(
      n,
      m[q] as number,
      m[q + 1] as number,
      m[q + 2] as number,
      m[q + 3] as number,
      m[q + 4] as number,
      kf.g,
      gx,
      gy,
    );
  }
}

/**
 * The World as it was when `kf` was taken, rebuilt from its motions (`ids[order[k]]` names body k):
 * obstacles first, then the bodies in id order, then the Zeno watch. Its future equals the original
 * World's bit for bit.
 */
export function worldAt(kf: Keyframe, ids: readonly string[], chains: ChainCache): World {
  const w = World.restoredAt(kf.time, kf.g, kf.gravity);
  for (const l of kf.lines) w.addLine(l.id, l.p1, l.p2, l.kind);
  for (const p of kf.points) w.addPoint(p.id, p.p);
  const { order, motions: m, props: p } = chains.arraysOf(kf, ids, (k, t) => loadMotions(k, t, chains));
  for (let k = 0; k < order.length; k++) {
    const q = k * KF_MOTION;
    w.restoreBodyMotion(ids[order[k] as number] as string, {
      t0: m[q] as number,
      x0: m[q + 1] as number,
      y0: m[q + 2] as number,
      vx: m[q + 3] as number,
      vy: m[q + 4] as number,
      r: p[3 * k] as number,
      m: p[3 * k + 1] as number,
      mu: p[3 * k + 2] as number,
    });
  }
  w.setZenoWatch(kf.zeno);
  return w;
}

/** Index of the last keyframe with time <= t (keyframes are in time order), or -1. */
export function keyframeAtOrBefore(kfs: readonly Keyframe[], t: number): number {
  let lo = 0;
  let hi = kfs.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if ((kfs[mid] as Keyframe).time <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo - 1;
}

/** Index of the last keyframe with record <= i, or -1. */
export function keyframeAtRecord(kfs: readonly Keyframe[], i: number): number {
  let lo = 0;
  let hi = kfs.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if ((kfs[mid] as Keyframe).record <= i) lo = mid + 1;
    else hi = mid;
  }
  return lo - 1;
}

/** Bytes held by a keyframe, not counting what it shares with `prev`. */
export function keyframeBytes(kf: Keyframe, prev: Keyframe | undefined): number {
  let bytes = 160;
  if (kf.delta !== null) {
    const { nums, rows, added, removed } = kf.delta;
    bytes += nums.byteLength + rows.byteLength + added.byteLength + removed.byteLength;
  }
  if (kf.full !== null) {
    bytes += kf.full.motions.byteLength;
    if (prev?.full?.order !== kf.full.order) bytes += kf.full.order.byteLength;
    if (prev?.full?.props !== kf.full.props) bytes += kf.full.props.byteLength;
  }
  if (prev?.lines !== kf.lines) bytes += 48 * kf.lines.length;
  if (prev?.points !== kf.points) bytes += 32 * kf.points.length;
  return bytes;
}
