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
 * The width adapts, without changing the pop order: a new queue is sized at its first peek from
 * every key queued so far; then every half turn of the ring the queue compares the entries it
 * loaded per bucket with its target and, far off, rebuilds with a width estimated from the keys in
 * the queue; a front that grows for long without the window moving does the same.
 */
import { CALENDAR_BUCKET_TARGET, CALENDAR_REBUILD_FACTOR } from "../tolerances.js";
import { FrontHeap } from "./frontHeap.js";

const INF = Number.POSITIVE_INFINITY;
/** Location of a slot: not queued, in the front heap, or in the overflow list (>= 0: ring bucket). */
const ABSENT = -1;
const FRONT = -2;
const OVERFLOW = -3;
/** Bucket numbers stay below this so that they are exact integers (and +1 moves them). */
const MAX_BUCKET = 2 ** 52;
/**
 * A front larger than this means the width is too large (the queue has become a binary heap). It
 * is rebuilt once the operations on it since the last rebuild outnumber both its entries (a bulk
 * fill into the front is rebuilt soon after it) and a quarter of all entries (so a front crowded
 * by many equal times cannot rebuild more often than every n / 4 operations).
 */
const FRONT_CROWDED = 64;

export class CalendarQueue {
  // `declare`: set in the constructor, never undefined, so V8 knows their types (bodyStore.ts).
  declare private key: Float64Array;
  declare private loc: Int32Array;
  /** Ring and overflow lists (per slot). */
  declare private next: Int32Array;
  declare private prev: Int32Array;
  /** Entries due in the current bucket or earlier. */
  declare private front: FrontHeap;
  private ring: Int32Array = new Int32Array(16).fill(-1);
  private mask = 15;
  private overHead = -1;
  private n = 0;
  private ringCount = 0;
  private overCount = 0;
  private origin = 0;
  private w = 1;
  private invW = 1;
  /**
   * Current bucket number: entries with a bucket number <= cur are in the front. Until the first
   * peek the queue has no width yet: cur and ringEnd are -Infinity, so every entry waits in the
   * overflow list (O(1) each), and the first peek sizes the queue from all of them at once.
   */
  private cur = -INF;
  /** Ring entries have cur < bucket < ringEnd <= cur + ring length. */
  private ringEnd = -INF;
  private sized = false;
  /** Adaptation counters since the last rebuild. */
  private advances = 0;
  private loaded = 0;
  private frontOps = 0;
  private overScanned = 0;
  private rebuilds = 0;

  constructor(capacity: number, tieLess: (a: number, b: number) => boolean) {
    const cap = Math.max(capacity, 4);
    this.key = new Float64Array(cap);
    this.loc = new Int32Array(cap).fill(ABSENT);
    this.next = new Int32Array(cap).fill(-1);
    this.prev = new Int32Array(cap).fill(-1);
    this.front = new FrontHeap(cap, tieLess);
  }

  get size(): number {
    return this.n;
  }

  /** Grow the slot range to at least `capacity`. */
  reserve(capacity: number): void {
    if (capacity <= this.loc.length) return;
    const cap = Math.max(capacity, this.loc.length * 2);
    const grow = <T extends Float64Array | Int32Array>(a: T, fill: number): T => {
      const b = (a instanceof Float64Array ? new Float64Array(cap) : new Int32Array(cap).fill(fill)) as T;
      b.set(a);
      return b;
    };
    this.key = grow(this.key, 0);
    this.loc = grow(this.loc, ABSENT);
    this.next = grow(this.next, -1);
    this.prev = grow(this.prev, -1);
    this.front.reserve(cap);
  }

  has(slot: number): boolean {
    const l = this.loc[slot];
    return l !== undefined && l !== ABSENT;
  }

  /** The slot with the smallest key (exact ties: the canonical order), or -1 when empty. */
  peek(): number {
    if (this.front.n === 0 && !this.refill()) return -1;
    return this.front.slots[0] as number;
  }

  peekKey(): number {
    if (this.front.n === 0 && !this.refill()) return INF;
    return this.front.keys[0] as number;
  }

  /** Insert the slot or change its key. An infinite key removes it (it would never be popped). */
  set(slot: number, key: number): void {
    if (key === INF) {
      this.remove(slot);
      return;
    }
    if (Number.isNaN(key)) throw new RangeError(`event queue: slot ${slot} was given a NaN time`);
    const l = this.loc[slot] as number;
    // Stored first: place reads it from here (a double passed to a call V8 does not inline is boxed).
    this.key[slot] = key;
    if (l === FRONT) {
      const b = Math.floor((key - this.origin) * this.invW);
      if (b <= this.cur) {
        this.front.update(slot, key);
        if (++this.frontOps > this.crowdLimit() && this.front.n > FRONT_CROWDED) this.rebuild();
        return;
      }
      this.front.remove(slot);
    } else if (l !== ABSENT) {
      this.unlink(slot, l);
    } else this.n++;
    this.place(slot);
  }

  remove(slot: number): void {
    const l = this.loc[slot];
    if (l === undefined || l === ABSENT) return; // not queued (or beyond the reserved range)
    if (l === FRONT) this.front.remove(slot);
    else this.unlink(slot, l);
    this.loc[slot] = ABSENT;
    this.n--;
  }

  /** Bucket width, ring length and rebuilds so far (for tests and benchmarks; never affects the order). */
  diagnostics(): { width: number; origin: number; buckets: number; rebuilds: number } {
    return { width: this.w, origin: this.origin, buckets: this.mask + 1, rebuilds: this.rebuilds };
  }

  /** A copy with another tie-break function (a cloned world passes its own). */
  cloneWith(tieLess: (a: number, b: number) => boolean): CalendarQueue {
    const q = new CalendarQueue(this.loc.length, tieLess);
    q.key.set(this.key);
    q.loc.set(this.loc);
    q.next.set(this.next);
    q.prev.set(this.prev);
    q.front = this.front.cloneWith(tieLess);
    q.ring = this.ring.slice();
    q.mask = this.mask;
    q.overHead = this.overHead;
    q.n = this.n;
    q.ringCount = this.ringCount;
    q.overCount = this.overCount;
    q.origin = this.origin;
    q.w = this.w;
    q.invW = this.invW;
    q.cur = this.cur;
    q.sized = this.sized;
    q.ringEnd = this.ringEnd;
    q.advances = this.advances;
    q.loaded = this.loaded;
    q.frontOps = this.frontOps;
    q.overScanned = this.overScanned;
    q.rebuilds = this.rebuilds;
    return q;
  }

  // ---- placement ----------------------------------------------------------------------------

  /**
   * Put a slot that is in no structure (counted in n) where its key, already in `key[slot]`,
   * belongs. The key is read here rather than passed: V8 does not inline this call, and a double
   * passed to it would be boxed (a heap allocation each, 5.7 per collision in a gas).
   */
  private place(slot: number): void {
    const key = this.key[slot] as number;
    const b = Math.floor((key - this.origin) * this.invW);
    if (b <= this.cur) {
      this.frontPush(slot, key);
      if (++this.frontOps > this.crowdLimit() && this.front.n > FRONT_CROWDED) this.rebuild();
    } else if (b < this.ringEnd) {
      const r = (b | 0) & this.mask; // b < 2^53: ToInt32 keeps the low bits exactly
      this.pushList(slot, this.ring[r] as number);
      this.ring[r] = slot;
      this.loc[slot] = r;
      this.ringCount++;
    } else {
      this.pushList(slot, this.overHead);
      this.overHead = slot;
      this.loc[slot] = OVERFLOW;
      this.overCount++;
    }
  }

  private pushList(slot: number, head: number): void {
    this.next[slot] = head;
    this.prev[slot] = -1;
    if (head >= 0) this.prev[head] = slot;
  }

  /** Take a slot out of its ring bucket (l >= 0) or the overflow list (l === OVERFLOW). */
  private unlink(slot: number, l: number): void {
    const p = this.prev[slot] as number;
    const q = this.next[slot] as number;
    if (p >= 0) this.next[p] = q;
    else if (l === OVERFLOW) this.overHead = q;
    else this.ring[l] = q;
    if (q >= 0) this.prev[q] = p;
    if (l === OVERFLOW) this.overCount--;
    else this.ringCount--;
  }

  /**
   * Move the window until the front holds something; false when the queue is empty. Empty buckets
   * are stepped over one at a time; when the ring is empty the window jumps to the overflow's
   * earliest bucket.
   */
  private refill(): boolean {
    while (this.front.n === 0) {
      if (this.ringCount === 0) {
        if (this.overCount === 0) return false;
        if (!this.sized) {
          this.rebuild();
          continue;
        }
        let m = INF;
        for (let s = this.overHead; s >= 0; s = this.next[s] as number) {
          const b = Math.floor(((this.key[s] as number) - this.origin) * this.invW);
          if (b < m) m = b;
        }
        this.overScanned += this.overCount;
        if (!(m < MAX_BUCKET)) {
          // Keys too far ahead for this width (bucket numbers past 2^52): start again from them.
          this.rebuild();
          continue;
        }
        this.cur = m - 1;
        this.pullOverflow();
      }
      this.cur++;
      this.advances++;
      if (this.cur >= this.ringEnd - ((this.mask + 1) >> 1)) {
        if (this.adaptDue()) {
          this.rebuild();
          continue;
        }
        this.pullOverflow();
      }
      const r = (this.cur | 0) & this.mask;
      let s = this.ring[r] as number;
      this.ring[r] = -1;
      while (s >= 0) {
        const nx = this.next[s] as number;
        this.ringCount--;
        this.loaded++;
        this.frontPush(s, this.key[s] as number);
        s = nx;
      }
    }
    return true;
  }

  /** Extend the window to cur + ring length and move the overflow entries it now covers into the ring. */
  private pullOverflow(): void {
    this.ringEnd = this.cur + this.mask + 1;
    this.overScanned += this.overCount;
    let s = this.overHead;
    while (s >= 0) {
      const nx = this.next[s] as number;
      const b = Math.floor(((this.key[s] as number) - this.origin) * this.invW);
      if (b < this.ringEnd) {
        this.unlink(s, OVERFLOW);
        this.n--;
        this.place(s);
        this.n++;
      }
      s = nx;
    }
  }

  private crowdLimit(): number {
    return Math.max(this.front.n, this.n >> 2) + FRONT_CROWDED;
  }

  /** Whether the bucket width is far enough from its target to pay for a rebuild. */
  private adaptDue(): boolean {
    if (this.advances < 64) return false;
    const perBucket = this.loaded / this.advances;
    return (
      perBucket > CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR ||
      perBucket < CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR ||
      this.overScanned > 8 * this.n + 1024
    );
  }

  /**
   * Re-place every entry with a width estimated from the queued keys (about CALENDAR_BUCKET_TARGET
   * entries per bucket near the front, if the keys ahead are spread like those queued) and a ring
   * of about two buckets per entry. Cost O(n); the counters make it rare.
   */
  private rebuild(): void {
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
    const lo = keys[0] ?? 0;
    // The median spread ahead of the earliest key: with keys spread like an exponential of mean
    // tau, the median is 0.69 tau and about n / tau entries fall due per unit of time.
    const spread = (keys[keys.length >> 1] ?? lo) - lo;
    const w = (CALENDAR_BUCKET_TARGET * spread) / (0.69 * Math.max(1, keys.length));
    if (w > 0 && Number.isFinite(1 / w)) {
      this.w = w;
      this.invW = 1 / w;
    }
    let nb = 16;
    while (nb < 2 * keys.length) nb *= 2;
    if (this.ring.length !== nb) this.ring = new Int32Array(nb);
    this.ring.fill(-1);
    this.mask = nb - 1;
    this.origin = lo;
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

  private frontPush(slot: number, key: number): void {
    this.loc[slot] = FRONT;
    this.front.push(slot, key);
  }
}
