/**
 * Calendar event queue over integer slots (one entry per body), keyed by a time: insert, re-key,
 * remove and peek at the earliest in O(1) expected time (it replaced a 4-ary heap, O(log n)).
 *
 * Time is cut into buckets of width `w` (bucket number floor((key - origin) / w), a monotone
 * function of the key). Entries in the current bucket or earlier sit in a small binary heap, the
 * "front", ordered by key and then by the caller's canonical tie order; entries of the next `nb`
 * buckets sit unsorted in doubly linked lists, one per bucket of a ring; later ones in an overflow
 * list, pulled into the ring as the window moves on. Because the bucket number never decreases
 * with the key, every entry outside the front has a strictly larger key than every entry in it, so
 * the front's top is the global minimum and ties never straddle two places: the pop order is the
 * (key, tie order) order whatever the bucket width, insertion order or history (determinism).
 *
 * The width adapts, without changing the pop order (calendarWidth.ts: when to rebuild, and with
 * what width). The buckets and the window are calendarBuckets.ts's; this class adds growing,
 * copying, re-sizing the slot range and the rebuild. (Split so, the gas counts the same instructions per collision as the
 * queue in one file: docs/engine-throughput.md, session 26.)
 */
import { ABSENT, CalendarBuckets } from "./calendarBuckets.js";
import { bucketWidth, ringLength } from "./calendarWidth.js";
import type { TieBreak } from "./frontHeap.js";

export class CalendarQueue extends CalendarBuckets {
  /** Grow the slot range to at least `capacity` (doubling: for a caller adding one slot at a time). */
  reserve(capacity: number): void {
    if (capacity > this.loc.length) this.resize(Math.max(capacity, this.loc.length * 2));
  }

  /** Number of slots it can hold (0 .. slotCapacity - 1). */
  get slotCapacity(): number {
    return this.loc.length;
  }

  /**
   * Set the slot range to exactly 0 .. capacity - 1 (the World's body store's capacity), keeping
   * every queued entry, its key and its place: a queued slot must be below `capacity` (a RangeError
   * otherwise, and nothing changes). The pop order is unchanged.
   */
  resize(capacity: number): void {
    for (let s = capacity; s < this.loc.length; s++)
      if (this.loc[s] !== ABSENT)
        throw new RangeError(`event queue: slot ${s} is queued, beyond the new range ${capacity}`);
    this.front.resize(capacity);
    const keep = Math.min(capacity, this.loc.length);
    const sized = <T extends Float64Array | Int32Array>(a: T, fill: number): T => {
      const b = (
        a instanceof Float64Array ? new Float64Array(capacity) : new Int32Array(capacity).fill(fill)
      ) as T;
      b.set(a.subarray(0, keep));
      return b;
    };
    this.key = sized(this.key, 0);
    this.loc = sized(this.loc, ABSENT);
    this.next = sized(this.next, -1);
    this.prev = sized(this.prev, -1);
  }

  /** Bucket width, ring length and rebuilds so far (for tests and benchmarks; never affects the order). */
  diagnostics(): { width: number; origin: number; buckets: number; rebuilds: number } {
    return { width: this.w, origin: this.origin, buckets: this.mask + 1, rebuilds: this.rebuilds };
  }

  /** A copy with another tie-break (a cloned world passes itself). */
  cloneWith(order: TieBreak): CalendarQueue {
    const q = new CalendarQueue(this.loc.length, order);
    // Every field, the same values in the same order (the same shape), then copies of the arrays.
    Object.assign(q, this);
    q.key = this.key.slice();
    q.loc = this.loc.slice();
    q.next = this.next.slice();
    q.prev = this.prev.slice();
    q.ring = this.ring.slice();
    q.front = this.front.cloneWith(order);
    return q;
  }

  /**
   * Re-place every entry with a width and a ring length estimated from the queued keys
   * (calendarWidth.ts). Cost O(n); the counters make it rare.
   */
  protected rebuild(): void {
    this.rebuilds++;
    this.sized = true;
    const all: number[] = [];
    for (let i = 0; i < this.front.n; i++) all.push(this.front.slots[i] as number);
    for (let r = 0; r <= this.mask; r++)
      for (let s = this.ring[r] as number; s >= 0; s = this.next[s] as number) all.push(s);
    for (let s = this.overHead; s >= 0; s = this.next[s] as number) all.push(s);
    const keys = new Float64Array(all.length);
    for (let i = 0; i < all.length; i++) keys[i] = this.key[all[i] as number] as number;
    keys.sort();
    const w = bucketWidth(keys);
    if (w > 0) {
      this.w = w;
      this.invW = 1 / w;
    }
    const nb = ringLength(keys.length);
    if (this.ring.length !== nb) this.ring = new Int32Array(nb);
    this.ring.fill(-1);
    this.mask = nb - 1;
    this.origin = keys[0] ?? 0;
    this.cur = 0;
    this.ringEnd = nb;
    this.front.n = 0;
    this.overHead = -1;
    this.ringCount = 0;
    this.overCount = 0;
    this.advances = 0;
    this.loaded = 0;
    this.frontOps = 0;
    this.overScanned = 0;
    for (const s of all) this.place(s);
  }
}
