/**
 * Storage of the discs of a World, indexed by slot. A slot holds one body's current motion (see
 * physics/motion.ts) as one record of 8 doubles in `mot` (t0, x0, y0, vx0, vy0, ax, ay, tEnd: a
 * pair test reads both bodies' motions, and one cache line each is fewer misses in large scenes
 * than eight arrays), and its properties and next predicted event in one array per field. Slots of
 * removed bodies are reused; a slot's `version` only ever grows, even across a trim, so a prediction
 * (or a memo) made against an older version of a partner is recognised as stale.
 *
 * Capacity: the per-slot arrays grow by GROWTH when full. `trim` gives back the unused slots (the
 * free slots at the end, then the arrays shrunk to the slots in use plus TRIM_SLACK) where the World rebuilds its
 * grid and predicts every body anyway (its prepare step, O(n) already); removals alone make the
 * next advance do so once the capacity is more than TRIM_AFTER times the slots in use (`trimDue`).
 * A live body never changes slot. The grid and the event queue are sized to `capacity` and follow
 * it (broadPhase.ts fitSlots). These sizing constants live here, not in tolerances.ts: they change
 * memory and copying, never a result.
 */
import { idOrderKey } from "./idOrder.js";

/**
 * Factor the per-slot arrays grow by when full: 1.5, not 2, so that a growth leaves a third of them
 * unused, not half, until the next trim (amortised cost: each slot copied about twice, not once).
 */
export const GROWTH = 1.5;
/** Fewest slots the arrays hold: a small world is not reallocated at each of its first bodies. */
export const MIN_SLOTS = 16;
/**
 * Removals alone make a trim due (and with it a grid rebuild and every body predicted again, O(n))
 * once the capacity is more than TRIM_AFTER times the slots in use: at least a third of the slots
 * were given up since the arrays were last sized, which pays for it (O(1) per removal).
 */
export const TRIM_AFTER = 1.5;
/**
 * Spare slots a trim leaves, as a fraction of the slots in use (rounded up). Without them a world
 * that gains one body per advance (an editor or a game adding a body at each instant: every add
 * marks the world for a rebuild) would regrow its arrays at the next add and trim them again at
 * the next advance: two O(n) copies per body. With n/16 spare slots that happens once per n/16
 * bodies added (about 32 slot copies per body), for about 6 % more slots.
 */
export const TRIM_SLACK = 1 / 16;

/** The capacity a trim leaves for `used` slots in use: TRIM_SLACK spare, at least MIN_SLOTS. */
export function trimmedCapacity(used: number): number {
  return Math.max(MIN_SLOTS, used + Math.ceil(used * TRIM_SLACK));
}

/** Internal event kinds of a body's next event. Ranks give the canonical order of simultaneous events. */
export const EV_NONE = 0;
export const EV_CROSS = 1;
export const EV_STOP = 2;
export const EV_LINE = 3;
export const EV_POINT = 4;
export const EV_BODY = 5;

const F64_FIELDS = [
  "r",
  "m",
  "mu",
  "version",
  "evTime",
  "evOtherVersion",
  "crossTime",
  "boxMinX",
  "boxMinY",
  "boxMaxX",
  "boxMaxY",
  "idKey",
] as const;
const I32_FIELDS = ["evKind", "evOther", "evAux", "crossDir"] as const;

export class BodyStore {
  // Fields first set in the constructor are `declare`d: a field declared without a value is defined
  // as undefined first (ES2022 class fields), and V8 then no longer knows which array it holds and
  // checks the array's map at every read (docs/engine-throughput.md, session 24).
  declare capacity: number;
  count = 0;
  /** Id of each live slot; undefined for free slots. */
  ids: (string | undefined)[] = [];
  private free: number[] = [];
  /** Version a slot starts from when it is first taken since a trim dropped it (see `trim`). */
  private versionFloor = 0;
  /** Current motion, 8 doubles per slot (one cache line): t0, x0, y0, vx0, vy0, ax, ay, tEnd. */
  declare mot: Float64Array;
  declare r: Float64Array;
  declare m: Float64Array;
  declare mu: Float64Array;
  declare version: Float64Array;
  /** Next predicted interaction (collision or stop) and with whom. */
  declare evTime: Float64Array;
  declare evOtherVersion: Float64Array;
  declare evKind: Int32Array;
  declare evOther: Int32Array;
  /** Line events: 0 = the line itself, 1 = its first end point, 2 = its second end point. */
  declare evAux: Int32Array;
  /** Next cell crossing and its direction (0: -x, 1: +x, 2: -y, 3: +y). */
  declare crossTime: Float64Array;
  declare crossDir: Int32Array;
  /** Bounding box of the whole remaining path including the radius (infinite when unbounded). */
  declare boxMinX: Float64Array;
  declare boxMinY: Float64Array;
  declare boxMaxX: Float64Array;
  declare boxMaxY: Float64Array;
  /** Order key of each slot's id (idOrder.ts): the response orders a colliding pair without reading the strings. */
  declare idKey: Float64Array;

  constructor(capacity = 16) {
    this.capacity = capacity;
    this.mot = new Float64Array(capacity * 8);
    this.r = new Float64Array(capacity);
    this.m = new Float64Array(capacity);
    this.mu = new Float64Array(capacity);
    this.version = new Float64Array(capacity);
    this.evTime = new Float64Array(capacity);
    this.evOtherVersion = new Float64Array(capacity);
    this.evKind = new Int32Array(capacity);
    this.evOther = new Int32Array(capacity);
    this.evAux = new Int32Array(capacity);
    this.crossTime = new Float64Array(capacity);
    this.crossDir = new Int32Array(capacity);
    this.boxMinX = new Float64Array(capacity);
    this.boxMinY = new Float64Array(capacity);
    this.boxMaxX = new Float64Array(capacity);
    this.boxMaxY = new Float64Array(capacity);
    this.idKey = new Float64Array(capacity);
  }

  /** Take a free slot for a new body (growing the arrays when full). */
  allocate(id: string): number {
    const slot = this.free.length > 0 ? (this.free.pop() as number) : this.count++;
    if (slot >= this.capacity) this.resize(Math.max(MIN_SLOTS, Math.ceil(this.capacity * GROWTH)));
    if ((this.version[slot] as number) < this.versionFloor) this.version[slot] = this.versionFloor;
    this.ids[slot] = id;
    this.idKey[slot] = idOrderKey(id);
    return slot;
  }

  release(slot: number): void {
    this.ids[slot] = undefined;
    this.version[slot] = (this.version[slot] as number) + 1;
    this.evKind[slot] = EV_NONE;
    this.free.push(slot);
  }

  /** Number of slots in use or free (iterate 0..slotCount and skip undefined ids). */
  get slotCount(): number {
    return this.count;
  }

  /** One past the last live slot (0 when there is none): the slots a trim keeps. */
  usedSlots(): number {
    let used = this.count;
    while (used > 0 && this.ids[used - 1] === undefined) used--;
    return used;
  }

  /** Whether removals left the capacity more than TRIM_AFTER times the slots in use. */
  trimDue(): boolean {
    // The live bodies first (O(1)): no trim is due while they alone fill the bound.
    if (this.capacity <= TRIM_AFTER * Math.max(MIN_SLOTS, this.count - this.free.length)) return false;
    return this.capacity > TRIM_AFTER * Math.max(MIN_SLOTS, this.usedSlots());
  }

  /**
   * Give back the unused slots: the free slots at the end are dropped (slotCount becomes
   * usedSlots()), then the arrays shrink to trimmedCapacity(slotCount) (TRIM_SLACK spare). Live bodies keep their
   * slots; the free slots before the last live one stay free, in the same order. Whether the
   * capacity changed (the grid and the queue then follow it). Every prediction must be made again
   * after a trim (World's prepare does): a prediction may name a dropped slot.
   */
  trim(): boolean {
    const used = this.usedSlots();
    if (used < this.count) {
      // The dropped slots' versions go with them: a slot taken again later starts above all of them.
      for (let s = used; s < this.count; s++)
        this.versionFloor = Math.max(this.versionFloor, (this.version[s] as number) + 1);
      this.free = this.free.filter((s) => s < used);
      this.ids.length = used;
      this.count = used;
    }
    const capacity = trimmedCapacity(used);
    if (capacity >= this.capacity) return false;
    this.resize(capacity);
    return true;
  }

  /** Reallocate the per-slot arrays to `capacity` slots (at least slotCount), keeping slots below it. */
  private resize(capacity: number): void {
    const keep = Math.min(capacity, this.capacity);
    for (const f of F64_FIELDS) {
      const a = new Float64Array(capacity);
      a.set(this[f].subarray(0, keep));
      this[f] = a;
    }
    const mot = new Float64Array(capacity * 8);
    mot.set(this.mot.subarray(0, keep * 8));
    this.mot = mot;
    for (const f of I32_FIELDS) {
      const a = new Int32Array(capacity);
      a.set(this[f].subarray(0, keep));
      this[f] = a;
    }
    this.capacity = capacity;
  }

  clone(): BodyStore {
    // empty arrays first (not `capacity` of each, thrown away at once: a Timeline clones its World
    // at every apply, where that was most of the cost for a small scene)
    const s = new BodyStore(0);
    s.capacity = this.capacity;
    s.count = this.count;
    s.ids = this.ids.slice();
    s.free = this.free.slice();
    s.versionFloor = this.versionFloor;
    for (const f of F64_FIELDS) s[f] = this[f].slice();
    for (const f of I32_FIELDS) s[f] = this[f].slice();
    s.mot = this.mot.slice();
    return s;
  }
}
