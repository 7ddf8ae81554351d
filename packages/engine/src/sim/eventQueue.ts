/**
 * Indexed 4-ary min-heap over integer slots (one entry per body), keyed by a time. Update, insert
 * and remove are O(log n). Keys are stored in heap order beside the slots, so sifting reads memory
 * sequentially. Exact ties in time are broken by a caller-supplied canonical order, so the pop
 * order never depends on insertion order (determinism).
 */
export class IndexedHeap {
  private slots: Int32Array;
  private keys: Float64Array;
  private pos: Int32Array;
  private n = 0;
  private readonly tieLess: (a: number, b: number) => boolean;

  constructor(capacity: number, tieLess: (a: number, b: number) => boolean) {
    const cap = Math.max(capacity, 4);
    this.slots = new Int32Array(cap);
    this.keys = new Float64Array(cap);
    this.pos = new Int32Array(cap).fill(-1);
    this.tieLess = tieLess;
  }

  get size(): number {
    return this.n;
  }

  /** Grow the slot range to at least `capacity`. */
  reserve(capacity: number): void {
    if (capacity <= this.pos.length) return;
    const cap = Math.max(capacity, this.pos.length * 2);
    const slots = new Int32Array(cap);
    slots.set(this.slots);
    const keys = new Float64Array(cap);
    keys.set(this.keys);
    const pos = new Int32Array(cap).fill(-1);
    pos.set(this.pos);
    this.slots = slots;
    this.keys = keys;
    this.pos = pos;
  }

  /** The slot with the smallest key, or -1 when empty. */
  peek(): number {
    return this.n > 0 ? (this.slots[0] as number) : -1;
  }

  peekKey(): number {
    return this.n > 0 ? (this.keys[0] as number) : Number.POSITIVE_INFINITY;
  }

  has(slot: number): boolean {
    return (this.pos[slot] as number) >= 0;
  }

  /** Insert the slot or change its key. An infinite key removes it (it would never be popped). */
  set(slot: number, key: number): void {
    if (key === Number.POSITIVE_INFINITY) {
      this.remove(slot);
      return;
    }
    const p = this.pos[slot] as number;
    if (p < 0) {
      this.up(this.n++, slot, key);
      return;
    }
    const old = this.keys[p] as number;
    if (key < old) this.up(p, slot, key);
    else if (key > old) this.down(p, slot, key);
    else {
      // Same time: the tie-break may have changed (another event at the same instant).
      this.up(p, slot, key);
      const q = this.pos[slot] as number;
      this.down(q, slot, key);
    }
  }

  remove(slot: number): void {
    const p = this.pos[slot];
    if (p === undefined || p < 0) return; // not queued (or beyond the reserved range)
    this.pos[slot] = -1;
    const last = --this.n;
    if (p === last) return;
    const ls = this.slots[last] as number;
    const lk = this.keys[last] as number;
    this.up(p, ls, lk);
    const q = this.pos[ls] as number;
    this.down(q, ls, lk);
  }

  /** A copy with another tie-break function (a cloned world passes its own). */
  cloneWith(tieLess: (a: number, b: number) => boolean): IndexedHeap {
    const h = new IndexedHeap(this.pos.length, tieLess);
    h.slots.set(this.slots);
    h.keys.set(this.keys);
    h.pos.set(this.pos);
    h.n = this.n;
    return h;
  }

  /** Place (slot, key) at position i or above. */
  private up(i: number, slot: number, key: number): void {
    const slots = this.slots;
    const keys = this.keys;
    const pos = this.pos;
    while (i > 0) {
      const parent = (i - 1) >> 2;
      const pk = keys[parent] as number;
      if (key > pk) break;
      const ps = slots[parent] as number;
      if (key === pk && !this.tieLess(slot, ps)) break;
      slots[i] = ps;
      keys[i] = pk;
      pos[ps] = i;
      i = parent;
    }
    slots[i] = slot;
    keys[i] = key;
    pos[slot] = i;
  }

  /** Place (slot, key) at position i or below. */
  private down(i: number, slot: number, key: number): void {
    const slots = this.slots;
    const keys = this.keys;
    const pos = this.pos;
    const n = this.n;
    for (;;) {
      const first = 4 * i + 1;
      if (first >= n) break;
      let c = first;
      let ck = keys[first] as number;
      if (first + 3 < n) {
        // Unrolled smallest of four (the hot loop); exact ties in key go to the canonical order.
        const k0 = ck;
        const k1 = keys[first + 1] as number;
        const k2 = keys[first + 2] as number;
        const k3 = keys[first + 3] as number;
        if (k1 < ck) {
          c = first + 1;
          ck = k1;
        }
        if (k2 < ck) {
          c = first + 2;
          ck = k2;
        }
        if (k3 < ck) {
          c = first + 3;
          ck = k3;
        }
        if ((k0 === ck ? 1 : 0) + (k1 === ck ? 1 : 0) + (k2 === ck ? 1 : 0) + (k3 === ck ? 1 : 0) > 1)
          c = this.minOfFew(first, first + 4);
      } else c = this.minOfFew(first, n);
      ck = keys[c] as number;
      if (ck > key) break;
      const cs = slots[c] as number;
      if (ck === key && !this.tieLess(cs, slot)) break;
      slots[i] = cs;
      keys[i] = ck;
      pos[cs] = i;
      i = c;
    }
    slots[i] = slot;
    keys[i] = key;
    pos[slot] = i;
  }

  /** Position of the smallest entry in [first, last), exact ties in key by the canonical order. */
  private minOfFew(first: number, last: number): number {
    const slots = this.slots;
    const keys = this.keys;
    let c = first;
    let ck = keys[first] as number;
    for (let j = first + 1; j < last; j++) {
      const jk = keys[j] as number;
      if (jk < ck || (jk === ck && this.tieLess(slots[j] as number, slots[c] as number))) {
        c = j;
        ck = jk;
      }
    }
    return c;
  }
}
