/**
 * Indexed binary min-heap over integer slots (one entry per body), keyed by a time. Update, insert
 * and remove are O(log n). Exact ties in time are broken by a caller-supplied canonical order, so
 * the pop order never depends on insertion order (determinism).
 */
export class IndexedHeap {
  private heap: Int32Array;
  private pos: Int32Array;
  private keys: Float64Array;
  private n = 0;
  private readonly tieLess: (a: number, b: number) => boolean;

  constructor(capacity: number, tieLess: (a: number, b: number) => boolean) {
    this.heap = new Int32Array(Math.max(capacity, 4));
    this.pos = new Int32Array(Math.max(capacity, 4)).fill(-1);
    this.keys = new Float64Array(Math.max(capacity, 4));
    this.tieLess = tieLess;
  }

  get size(): number {
    return this.n;
  }

  /** Grow the slot range to at least `capacity`. */
  reserve(capacity: number): void {
    if (capacity <= this.pos.length) return;
    const cap = Math.max(capacity, this.pos.length * 2);
    const heap = new Int32Array(cap);
    heap.set(this.heap);
    const pos = new Int32Array(cap).fill(-1);
    pos.set(this.pos);
    const keys = new Float64Array(cap);
    keys.set(this.keys);
    this.heap = heap;
    this.pos = pos;
    this.keys = keys;
  }

  /** The slot with the smallest key, or -1 when empty. */
  peek(): number {
    return this.n > 0 ? (this.heap[0] as number) : -1;
  }

  peekKey(): number {
    return this.n > 0 ? (this.keys[this.heap[0] as number] as number) : Number.POSITIVE_INFINITY;
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
    this.keys[slot] = key;
    const p = this.pos[slot] as number;
    if (p < 0) {
      const i = this.n++;
      this.heap[i] = slot;
      this.pos[slot] = i;
      this.up(i);
    } else {
      this.up(p);
      this.down(this.pos[slot] as number);
    }
  }

  remove(slot: number): void {
    const p = this.pos[slot] as number;
    if (p < 0) return;
    this.pos[slot] = -1;
    const last = this.heap[--this.n] as number;
    if (p === this.n) return;
    this.heap[p] = last;
    this.pos[last] = p;
    this.up(p);
    this.down(this.pos[last] as number);
  }

  /** A copy with another tie-break function (a cloned world passes its own). */
  cloneWith(tieLess: (a: number, b: number) => boolean): IndexedHeap {
    const h = new IndexedHeap(this.pos.length, tieLess);
    h.heap.set(this.heap);
    h.pos.set(this.pos);
    h.keys.set(this.keys);
    h.n = this.n;
    return h;
  }

  private less(a: number, b: number): boolean {
    const ka = this.keys[a] as number;
    const kb = this.keys[b] as number;
    return ka < kb || (ka === kb && this.tieLess(a, b));
  }

  private up(i: number): void {
    const heap = this.heap;
    const slot = heap[i] as number;
    while (i > 0) {
      const parent = (i - 1) >> 1;
      const ps = heap[parent] as number;
      if (!this.less(slot, ps)) break;
      heap[i] = ps;
      this.pos[ps] = i;
      i = parent;
    }
    heap[i] = slot;
    this.pos[slot] = i;
  }

  private down(i: number): void {
    const heap = this.heap;
    const n = this.n;
    const slot = heap[i] as number;
    for (;;) {
      const l = 2 * i + 1;
      if (l >= n) break;
      const r = l + 1;
      let c = l;
      if (r < n && this.less(heap[r] as number, heap[l] as number)) c = r;
      const cs = heap[c] as number;
      if (!this.less(cs, slot)) break;
      heap[i] = cs;
      this.pos[cs] = i;
      i = c;
    }
    heap[i] = slot;
    this.pos[slot] = i;
  }
}
