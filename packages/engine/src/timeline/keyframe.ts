/**
 * Keyframes of a Timeline: the state of all bodies' motions at one point of the computation, taken
 * after every group of actions and every K records (K grows with the number of bodies so keyframes
 * cost a bounded number of bytes per event). Every few keyframes also hold a World clone, the points
 * a recomputation restarts from. stateAt(t) = the last keyframe at or before t + the records up to t.
 */
import type { Vec2 } from "../scene/types.js";
import type { LineState, PointState } from "../sim/types.js";
import type { World } from "../sim/world.js";
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
  /** live body numbers sorted by id */
  order: Uint32Array;
  /** STRIDE numbers per body of `order` */
  motions: Float64Array;
  lines: LineState[];
  points: PointState[];
  /** body numbers and obstacle numbers allocated so far */
  bodyCount: number;
  lineCount: number;
  pointCount: number;
  /** id → number maps of obstacles alive at the keyframe */
  lineNums: Map<string, number>;
  pointNums: Map<string, number>;
  /** a World clone to restart a recomputation from, or null */
  world: World | null;
}

/** Copy the motions of the bodies in `order` out of `table`. */
export function snapshotMotions(table: MotionTable, order: Uint32Array): Float64Array {
  const out = new Float64Array(order.length * STRIDE);
  const d = table.data;
  for (let k = 0; k < order.length; k++) {
    const o = (order[k] as number) * STRIDE;
    out.set(d.subarray(o, o + STRIDE), k * STRIDE);
  }
  return out;
}

/** Load a keyframe's motions into `table` (which must have room for kf.bodyCount bodies). */
export function loadMotions(kf: Keyframe, table: MotionTable): void {
  table.ensure(kf.bodyCount);
  for (let k = 0; k < kf.order.length; k++) table.load(kf.order[k] as number, kf.motions, k * STRIDE);
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

/** Bytes held by a keyframe, not counting its World clone. */
export function keyframeBytes(kf: Keyframe): number {
  return kf.order.byteLength + kf.motions.byteLength + 48 * (kf.lines.length + kf.points.length) + 128;
}
