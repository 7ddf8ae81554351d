/**
 * Reading delta keyframes (keyframeDelta.ts makes them). A delta keyframe stands for the full
 * keyframe of its point: the chain of deltas back to the last full keyframe (its *chain*; depth 0 is
 * the full one, depth d the d-th delta after it) applied in order. What a read of a delta needs of
 * its chain is kept in a ChainIndex (chainIndex.ts), built once per chain and extended as deltas are
 * added to it.
 *
 * ChainCache: the read caches of one Timeline (TimelineCore.chains; every reader of a delta is given
 * its core's): the CHAIN_INDEXES chain indexes last used (a reader keeps asking the same chain or the
 * next one) and the order and arrays of the last keyframe asked for. They belong to their Timeline,
 * so a Timeline that is dropped takes its cached keyframes with it, and two Timelines read
 * alternately do not evict each other's entries. Entries are found by keyframe object, and
 * keyframes never change, so an entry can never give a stale answer: after an edit in the past the
 * new keyframes grow a branch beside the index of the chain it cut (kept, as an undo gives the old
 * keyframes back), and forgetBefore, which replaces every keyframe object, clears the cache (none of
 * it could hit again, and it would keep the forgotten keyframes reachable).
 * - orderOf(kf, ids), arraysOf(kf, ids, load): the live order, and the arrays a full keyframe of
 *   the point would hold, of any keyframe (the last one asked for kept).
 * - loadDelta(kf, table, loadFull): a delta keyframe's motions (loadFull loads a full keyframe's).
 *   It walks the deltas from the keyframe back to the full one and loads each body's newest row only
 *   (a body a hundred deltas touched was loaded a hundred times), then the full keyframe's bodies no
 *   row covered: the same numbers as loading every row in order, since a row's load overwrites
 *   everything the previous one wrote.
 * Free functions, no cache:
 * - patchDelta(kf, table): a table holding the motions of kf's `prev` (plus any records replayed
 *   since: every body they touched has a row in kf) becomes kf's, by loading kf's own rows only.
 * - rowOf(kf, n), loadOwnRow(kf, k, table): one body's row in kf's own delta.
 */
import { ChainIndex } from "./chainIndex.js";
import type { Keyframe, KeyframeArrays, KeyframeDelta } from "./keyframe.js";
import { DELTA_ROW } from "./keyframeDelta.js";
import { MotionTable, STRIDE } from "./motionTable.js";

/** Chain indexes a Timeline keeps (the last used): a reader scrubbing over one chain, a path
 *  crossing into the next, an edit's branch beside the history it replaces. Each holds 12 bytes per
 *  body. */
const CHAIN_INDEXES = 4;

/** The read caches of one Timeline (see the header). */
export class ChainCache {
  /** The indexes last used, the most recent last. */
  private indexes: ChainIndex[] = [];
  /** The last keyframe whose order or arrays were asked for, and them. */
  private last: { kf: Keyframe | null; order: Uint32Array; arrays: KeyframeArrays | null } = {
    kf: null,
    order: new Uint32Array(0),
    arrays: null,
  };
  /** @internal What the cache had to make, for tests: chain indexes built (a chain new to it, or
   *  a branch), and orders mapped (orderOf or arraysOf of a keyframe other than the last one). */
  readonly made = { indexes: 0, orders: 0 };

  /** Forget everything (forgetBefore: every keyframe was replaced). */
  clear(): void {
    this.indexes = [];
    this.last = { kf: null, order: new Uint32Array(0), arrays: null };
  }

  /** @internal Whether the cache references `kf` (tests: what a cache keeps reachable). */
  holds(kf: Keyframe): boolean {
    return this.last.kf === kf || this.indexes.some((index) => index.depth.has(kf));
  }

  /** Live body numbers of `kf` sorted by id (`ids[n]` names body n, as for worldAt). */
  orderOf(kf: Keyframe, ids: readonly string[]): Uint32Array {
    if (kf.full !== null) return kf.full.order;
    if (this.last.kf === kf) return this.last.order;
    const { index, d } = this.indexOf(kf);
    const order = index.mapOrder(d, ids);
    this.made.orders++;
    this.last = { kf, order, arrays: null };
    return order;
  }

  /** The arrays a full keyframe of `kf`'s point holds. */
  arraysOf(
    kf: Keyframe,
    ids: readonly string[],
    load: (k: Keyframe, t: MotionTable) => void,
  ): KeyframeArrays {
    if (kf.full !== null) return kf.full;
    if (this.last.kf === kf && this.last.arrays !== null) return this.last.arrays;
    const order = this.orderOf(kf, ids);
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
    this.last = { kf, order, arrays };
    return arrays;
  }

  /** Load a delta keyframe's motions into `table` (see the header; loadFull loads a full keyframe
   *  into it, but the bodies marked: marks[n] === mark). */
  loadDelta(
    kf: Keyframe,
    table: MotionTable,
    loadFull: (full: Keyframe, marks: Uint32Array, mark: number) => void,
  ): void {
    const { index, d } = this.indexOf(kf);
    table.ensure(kf.bodyCount);
    const m = newMarks(kf.bodyCount);
    for (let j = d; j >= 1; j--) {
      const delta = (index.members[j] as Keyframe).delta as KeyframeDelta;
      const nums = delta.nums;
      for (let k = 0; k < nums.length; k++) {
        const n = nums[k] as number;
        if (marks[n] === m) continue;
        marks[n] = m;
        loadRow(delta, k, table, kf);
      }
    }
    loadFull(index.members[0] as Keyframe, marks, m);
  }

  /** The index of `kf`'s chain (a delta keyframe) and kf's depth in it. */
  private indexOf(kf: Keyframe): { index: ChainIndex; d: number } {
    const indexes = this.indexes;
    for (let i = indexes.length - 1; i >= 0; i--) {
      const index = indexes[i] as ChainIndex;
      const d = index.depth.get(kf);
      if (d === undefined) continue;
      if (i !== indexes.length - 1) indexes.push(...indexes.splice(i, 1));
      return { index, d };
    }
    // walk back to a keyframe an index knows, or to the full keyframe
    const newer: Keyframe[] = [];
    let k = kf;
    let known: { index: ChainIndex; at: number } | null = null;
    while (k.delta !== null && known === null) {
      newer.push(k);
      k = k.delta.prev;
      for (const index of indexes) {
        const at = index.depth.get(k);
        if (at !== undefined) known = { index, at };
      }
    }
    newer.reverse();
    let index: ChainIndex;
    if (known !== null && known.at === known.index.tip) {
      index = known.index;
      index.extend(newer);
      indexes.splice(indexes.indexOf(index), 1);
    } else {
      // a new chain, or a branch off a known one (an edit in the past cut the chain and grew another)
      const base = known === null ? [k] : known.index.members.slice(0, known.at + 1);
      index = new ChainIndex(base.concat(newer));
      this.made.indexes++;
      if (indexes.length === CHAIN_INDEXES) indexes.shift();
    }
    indexes.push(index);
    return { index, d: index.tip }; // (kf is the newest member)
  }
}

/** Body numbers marked during one load (marks[n] === mark): the rows already loaded. Shared by
 *  every Timeline: a scratch buffer that holds no keyframe data, only stamps of body numbers, and
 *  meaningful only inside one loadDelta (which takes a fresh mark and runs to its end without
 *  another load: loadFull reads the marks and loads nothing through a cache). */
let marks = new Uint32Array(0);
let mark = 0;

function newMarks(bodyCount: number): number {
  if (marks.length < bodyCount || mark === 0xffffffff) {
    marks = new Uint32Array(Math.max(bodyCount, 2 * marks.length));
    mark = 0;
  }
  return ++mark;
}

/** Load row k of `delta` into `table` (as a full keyframe loads a body). */
function loadRow(delta: KeyframeDelta, k: number, table: MotionTable, kf: Keyframe): void {
  const { nums, rows } = delta;
  const n = nums[k] as number;
  const q = k * DELTA_ROW;
  table.setProps(n, rows[q + 5] as number, rows[q + 6] as number, rows[q + 7] as number);
  const r = (j: number) => rows[q + j] as number;
  table.start(n, r(0), r(1), r(2), r(3), r(4), kf.g, kf.gravity[0], kf.gravity[1]);
}

/** Turn `table`, holding the motions of `kf.delta.prev` (see the header), into kf's. */
export function patchDelta(kf: Keyframe, table: MotionTable): void {
  const delta = kf.delta as KeyframeDelta;
  table.ensure(kf.bodyCount);
  for (let k = 0; k < delta.nums.length; k++) loadRow(delta, k, table, kf);
}

/** Row of body n in `kf`'s own delta, or -1. */
export function rowOf(kf: Keyframe, n: number): number {
  return (kf.delta as KeyframeDelta).nums.indexOf(n);
}

/** Load row k of kf's own delta into `table`. */
export function loadOwnRow(kf: Keyframe, k: number, table: MotionTable): void {
  table.ensure(kf.bodyCount);
  loadRow(kf.delta as KeyframeDelta, k, table, kf);
}
