/**
 * The calendar queue's front (calendarQueue.ts): a binary min-heap of slots ordered by key, exact
 * ties by the caller's canonical order, so the order never depends on insertion order. It holds
 * the entries of the current bucket only, a handful, so a binary heap is the cheapest choice.
 * Each slot's heap position is kept (`pos`, one entry per slot of the queue's range) for O(log n)
 * update and removal; the heap itself (`slots`, `keys`) is sized to the entries it has held, at
 * least FRONT_START, doubled when full: a handful, not one per slot.
 */

/**
 * The canonical order of two slots whose keys are exactly equal. An object with a method, not a
 * function: the World passes itself, so the call that optimised code makes is to one method shared
 * by every World. A closure made per World (as before session 29) was embedded in that code, which
 * V8 threw away when the World died (docs/engine-throughput.md, session 29).
 */
export interface TieBreak {
  tieLess(a: number, b: number): boolean;
}

/** Entries the heap's arrays start with (a gas's front holds a few; 12 bytes each). */
const FRONT_START = 16;

export class FrontHeap {
  /** Slots and their keys in heap order; n entries (`declare`: never undefined, see bodyStore.ts). */
  declare slots: Int32Array;
  declare keys: Float64Array;
  n = 0;
  /** Heap position of each slot in the heap (meaningless for slots not in it). */
  declare private pos: Int32Array;
  /** `declare`d: set only in the constructor, never undefined first (see bodyStore.ts). */
  declare private readonly order: TieBreak;

  /** A heap for slots 0 .. capacity - 1. */
  constructor(capacity: number, order: TieBreak) {
    this.slots = new Int32Array(FRONT_START);
    this.keys = new Float64Array(FRONT_START);
    this.pos = new Int32Array(capacity).fill(-1);
    this.order = order;
  }

  /** Number of slots it can hold (0 .. slotCapacity - 1). */
  get slotCapacity(): number {
    return this.pos.length;
  }

  /**
   * Set the slot range to 0 .. capacity - 1, keeping every entry; a slot in the heap must be below
   * `capacity` (a RangeError otherwise, and nothing changes).
   */
  resize(capacity: number): void {
    for (let i = 0; i < this.n; i++)
      if ((this.slots[i] as number) >= capacity)
        throw new RangeError(`front heap: slot ${this.slots[i]} is queued, beyond the new range ${capacity}`);
    const pos = new Int32Array(capacity).fill(-1);
    pos.set(this.pos.subarray(0, Math.min(capacity, this.pos.length)));
    this.pos = pos;
  }

  /** A copy with another tie-break. */
  cloneWith(order: TieBreak): FrontHeap {
    const h = new FrontHeap(0, order);
    h.slots = this.slots.slice();
    h.keys = this.keys.slice();
    h.pos = this.pos.slice();
    h.n = this.n;
    return h;
  }

  push(slot: number, key: number): void {
    if (this.n === this.slots.length) this.growEntries();
    this.up(this.n++, slot, key);
  }

  /** Double the heap's arrays (kept apart from push, which V8 then still inlines). */
  private growEntries(): void {
    const slots = new Int32Array(2 * this.slots.length);
    slots.set(this.slots);
    const keys = new Float64Array(2 * this.keys.length);
    keys.set(this.keys);
    this.slots = slots;
    this.keys = keys;
  }

  /** Remove a slot that is in the heap. */
  remove(slot: number): void {
    const p = this.pos[slot] as number;
    const last = --this.n;
    if (p === last) return;
    this.place(p, this.slots[last] as number, this.keys[last] as number);
  }

  /** Change the key of a slot that is in the heap. */
  update(slot: number, key: number): void {
    this.place(this.pos[slot] as number, slot, key);
  }

  private before(ka: number, a: number, kb: number, b: number): boolean {
    return ka < kb || (ka === kb && this.order.tieLess(a, b));
  }

  /** Put (slot, key) at position p, moving it up or down as needed. */
  private place(p: number, slot: number, key: number): void {
    const parent = (p - 1) >> 1;
    if (p > 0 && this.before(key, slot, this.keys[parent] as number, this.slots[parent] as number))
      this.up(p, slot, key);
    else this.down(p, slot, key);
  }

  private up(i: number, slot: number, key: number): void {
    const fs = this.slots;
    const fk = this.keys;
    while (i > 0) {
      const parent = (i - 1) >> 1;
      const pk = fk[parent] as number;
      const ps = fs[parent] as number;
      if (!this.before(key, slot, pk, ps)) break;
      fs[i] = ps;
      fk[i] = pk;
      this.pos[ps] = i;
      i = parent;
    }
    fs[i] = slot;
    fk[i] = key;
    this.pos[slot] = i;
  }

  private down(i: number, slot: number, key: number): void {
    const fs = this.slots;
    const fk = this.keys;
    const n = this.n;
    for (;;) {
      let c = 2 * i + 1;
      if (c >= n) break;
      let ck = fk[c] as number;
      if (c + 1 < n && this.before(fk[c + 1] as number, fs[c + 1] as number, ck, fs[c] as number)) {
        c++;
        ck = fk[c] as number;
      }
      const cs = fs[c] as number;
      if (!this.before(ck, cs, key, slot)) break;
      fs[i] = cs;
      fk[i] = ck;
      this.pos[cs] = i;
      i = c;
    }
    fs[i] = slot;
    fk[i] = key;
    this.pos[slot] = i;
  }
}
