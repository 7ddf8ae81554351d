/**
 * BodyArrays: every body at one time as a structure of arrays (World.bodyArrays,
 * Timeline.bodyArraysAt), for reading thousands of bodies per frame without an object per body.
 * Body k is ids[k], x[k], y[k], ...; bodies sorted by id, and every number bit for bit what
 * `bodies(t)` / `stateAt(t).bodies` give (the same closed-form evaluation as bodyState.ts).
 *
 * Reuse (`into`, a previous result): the result IS `into`, updated in place (time, count, ids and
 * the arrays). Each Float64Array of `into` is kept when its length equals the new count, else
 * replaced by a new one, so every array is always exactly `count` long. `ids` stays the very same
 * array object when the ids are unchanged (a consumer compares it by reference to know whether the
 * set of bodies changed), else it is a new array. Here: the checks of `into`, the reuse, and the
 * World's writer with its cache of the bodies in id order (SortedSlots).
 */
import { positionAt, velocityAt } from "../physics/motion.js";
import { requireStarted } from "./bodyState.js";
import type { BodyStore } from "./bodyStore.js";
import { given } from "./refusalText.js";

/**
 * All bodies at one time, one entry per body in each array, sorted by id: body k is `ids[k]` at
 * (`x[k]`, `y[k]`) with velocity (`vx[k]`, `vy[k]`), acceleration (`ax[k]`, `ay[k]`), radius
 * `r[k]`, mass `m[k]` and friction coefficient `mu[k]`, the numbers of its BodyState bit for bit.
 * Every array is exactly `count` long.
 */
export interface BodyArrays {
  time: number;
  count: number;
  ids: readonly string[];
  x: Float64Array;
  y: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  ax: Float64Array;
  ay: Float64Array;
  r: Float64Array;
  m: Float64Array;
  mu: Float64Array;
}

/** The Float64Array fields of a BodyArrays. */
export const ARRAY_FIELDS = ["x", "y", "vx", "vy", "ax", "ay", "r", "m", "mu"] as const;

/** Why `into` cannot be reused (null: it can, or it is undefined), for the caller's own error. */
export function intoProblem(into: unknown): string | null {
  if (into === undefined) return null;
  if (typeof into !== "object" || into === null)
    return `must be a previous result or undefined (got ${given(into)})`;
  const o = into as Record<string, unknown>;
  if (!Array.isArray(o.ids)) return "must be a previous result: its ids is not an array";
  for (const f of ARRAY_FIELDS)
    if (!(o[f] instanceof Float64Array)) return `must be a previous result: its ${f} is not a Float64Array`;
  return null;
}

/** Whether `ids` holds exactly `count` ids, the k-th being `idAt(k)`. */
function sameIds(ids: readonly string[], count: number, idAt: (k: number) => string): boolean {
  if (ids.length !== count) return false;
  for (let k = 0; k < count; k++) if (ids[k] !== idAt(k)) return false;
  return true;
}

/**
 * The object to write `count` bodies at time t into: `into` updated (its arrays kept where their
 * length is `count`), or a new one. Its ids: into.ids when it holds the same ids as `idAt` gives,
 * else `fresh()` (called only then). The arrays' contents are left for the caller to write.
 */
export function arraysFor(
  t: number,
  count: number,
  idAt: (k: number) => string,
  fresh: () => readonly string[],
  into: BodyArrays | undefined,
): BodyArrays {
  const out: BodyArrays =
    into ??
    ({
      time: t,
      count,
      ids: [],
      x: new Float64Array(count),
      y: new Float64Array(count),
      vx: new Float64Array(count),
      vy: new Float64Array(count),
      ax: new Float64Array(count),
      ay: new Float64Array(count),
      r: new Float64Array(count),
      m: new Float64Array(count),
      mu: new Float64Array(count),
    } satisfies BodyArrays);
  out.time = t;
  out.count = count;
  if (into === undefined || !sameIds(into.ids, count, idAt)) out.ids = fresh();
  for (const f of ARRAY_FIELDS) if (out[f].length !== count) out[f] = new Float64Array(count);
  return out;
}

/**
 * @internal (the World's own cache, left out of the shipped types with its ReadonlyMap.)
 * The live slots of a BodyStore in id order, with their ids, kept between reads: sorting 20,000
 * ids costs more than reading their states. Checked at each read against the store (one array read
 * and one string comparison per body), so no edit needs to tell it; rebuilt when bodies were added,
 * removed or re-added in other slots. Its `ids` array may be handed out (it is replaced, never
 * changed, so a result holding it stays as it was; a caller writing into it only forces a rebuild).
 */
export class SortedSlots {
  private slots = new Int32Array(0);
  private sortedIds: readonly string[] = [];

  /** The slots of the bodies in `index` (id → slot, the World's), in id order, and their ids. */
  of(store: BodyStore, index: ReadonlyMap<string, number>): { slots: Int32Array; ids: readonly string[] } {
    if (!this.current(store, index)) {
      const ids = [...index.keys()].sort();
      this.slots = Int32Array.from(ids, (id) => index.get(id) as number);
      this.sortedIds = ids;
    }
    return { slots: this.slots, ids: this.sortedIds };
  }

  private current(store: BodyStore, index: ReadonlyMap<string, number>): boolean {
    const ids = this.sortedIds;
    if (index.size !== ids.length || this.slots.length !== ids.length) return false;
    const stored = store.ids;
    for (let k = 0; k < ids.length; k++) if (stored[this.slots[k] as number] !== ids[k]) return false;
    return true;
  }
}

/**
 * The World's bodies at time t into a BodyArrays (see arraysFor for `into`), each state as
 * bodyState.ts's stateOf computes it. The caller has checked t against the next event; a t before
 * a body's motion throws the ChapgameError stateOf throws (for the first such body in id order),
 * before anything is written.
 */
export function writeWorldArrays(
  b: BodyStore,
  sorted: { slots: Int32Array; ids: readonly string[] },
  t: number,
  into: BodyArrays | undefined,
): BodyArrays {
  const { slots, ids } = sorted;
  const n = slots.length;
  for (let k = 0; k < n; k++) requireStarted(b, slots[k] as number, t);
  const out = arraysFor(
    t,
    n,
    (k) => ids[k] as string,
    () => ids,
    into,
  );
  const { r, m, mu } = out;
  const mot = b.mot;
  for (let k = 0; k < n; k++) {
    const s = slots[k] as number;
    writeMotionAt(out, k, mot, s * 8, t);
    r[k] = b.r[s] as number;
    m[k] = b.m[s] as number;
    mu[k] = b.mu[s] as number;
  }
  return out;
}

/**
 * Writes body k's position, velocity and acceleration at t into `out`, from a motion record at
 * `d[o..o+7]` laid out as t0, x0, y0, vx, vy, ax, ay, tEnd (the World's body store and the
 * Timeline's motion table both start their records so): the closed form of bodyState.ts.
 */
export function writeMotionAt(out: BodyArrays, k: number, d: Float64Array, o: number, t: number): void {
  const t0 = d[o] as number;
  const a = d[o + 5] as number;
  const c = d[o + 6] as number;
  const tEnd = d[o + 7] as number;
  const te = Math.min(t, tEnd);
  const moving = t < tEnd;
  out.x[k] = positionAt(t0, d[o + 1] as number, d[o + 3] as number, a, te);
  out.y[k] = positionAt(t0, d[o + 2] as number, d[o + 4] as number, c, te);
  out.vx[k] = moving ? velocityAt(t0, d[o + 3] as number, a, t) : 0;
  out.vy[k] = moving ? velocityAt(t0, d[o + 4] as number, c, t) : 0;
  out.ax[k] = moving ? a : 0;
  out.ay[k] = moving ? c : 0;
}
