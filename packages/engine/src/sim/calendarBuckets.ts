/**
 * The calendar queue's buckets (calendarQueue.ts has the contract): each slot's place, in the front
 * heap (the current bucket or earlier), a ring bucket's list or the overflow list; inserting,
 * re-keying and removing entries, and moving the window on to the next bucket that holds any.
 * Growing, copying and re-sizing the buckets are calendarQueue.ts's.
 */
import { rebuildDue } from "./calendarWidth.js";
import { FrontHeap, type TieBreak } from "./frontHeap.js";

const INF = Number.POSITIVE_INFINITY;
/** Location of a slot: not queued, in the front heap, or in the overflow list (>= 0: ring bucket). */
export const ABSENT = -1;
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

export abstract class CalendarBuckets {
  // `declare`: set in the constructor, never undefined, so V8 knows their types (bodyStore.ts).
  declare protected key: Float64Array;
  declare protected loc: Int32Array;
  /** Ring and overflow lists (per slot). */
  declare protected next: Int32Array;
  declare protected prev: Int32Array;
  /** Entries due in the current bucket or earlier. */
  declare protected front: FrontHeap;
  protected ring: Int32Array = new Int32Array(16).fill(-1);
  protected mask = 15;
  protected overHead = -1;
  protected n = 0;
  protected ringCount = 0;
  protected overCount = 0;
  protected origin = 0;
  protected w = 1;
  protected invW = 1;
  /**
   * Current bucket number: entries with a bucket number <= cur are in the front. Until the first
   * peek the queue has no width yet: cur and ringEnd are -Infinity, so every entry waits in the
   * overflow list (O(1) each), and the first peek sizes the queue from all of them at once.
   */
  protected cur = -INF;
  /** Ring entries have cur < bucket < ringEnd <= cur + ring length. */
  protected ringEnd = -INF;
  protected sized = false;
  /** Adaptation counters since the last rebuild. */
  protected advances = 0;
  protected loaded = 0;
  protected frontOps = 0;
  protected overScanned = 0;
  protected rebuilds = 0;

  constructor(capacity: number, order: TieBreak) {
    const cap = Math.max(capacity, 4);
    this.key = new Float64Array(cap);
    this.loc = new Int32Array(cap).fill(ABSENT);
    this.next = new Int32Array(cap).fill(-1);
    this.prev = new Int32Array(cap).fill(-1);
    this.front = new FrontHeap(cap, order);
  }

  get size(): number {
    return this.n;
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

  /**
   * Put a slot that is in no structure (counted in n) where its key, already in `key[slot]`,
   * belongs. The key is read here rather than passed: V8 does not inline this call, and a double
   * passed to it would be boxed (a heap allocation each, 5.7 per collision in a gas).
   */
  protected place(slot: number): void {
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

  protected pushList(slot: number, head: number): void {
    this.next[slot] = head;
    this.prev[slot] = -1;
    if (head >= 0) this.prev[head] = slot;
  }

  /** Take a slot out of its ring bucket (l >= 0) or the overflow list (l === OVERFLOW). */
  protected unlink(slot: number, l: number): void {
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
  protected refill(): boolean {
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
        if (rebuildDue(this.advances, this.loaded, this.overScanned, this.n)) {
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
  protected pullOverflow(): void {
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

  protected crowdLimit(): number {
    return Math.max(this.front.n, this.n >> 2) + FRONT_CROWDED;
  }

  /** Re-place every entry with a new width (calendarQueue.ts). */
  protected abstract rebuild(): void;

  protected frontPush(slot: number, key: number): void {
    this.loc[slot] = FRONT;
    this.front.push(slot, key);
  }
}
