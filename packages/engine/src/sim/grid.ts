/**
 * Broad phase: a uniform grid of cells over the region the bodies occupy, with cell-crossing events.
 *
 * Why a grid with crossing events (and not swept boxes): discs have bounded radii, so with a cell
 * side w >= 2 * maxR two discs in contact are always in the same or adjacent cells; a body's
 * neighbourhood changes only when its centre crosses a cell boundary, which is itself an exact
 * event (a root of a degree <= 2 polynomial). Each event then costs O(1) pair tests plus O(log N) in
 * the event queue, whatever N is. Swept boxes need a time bound per box and re-insertion when it
 * expires, which costs more per event for the dilute gases this engine is built for.
 *
 * The outermost rows and columns extend to infinity, so a body leaving the region stays in an edge
 * cell and causes no more crossing events (a disc flying away for ever costs nothing). Cells are
 * doubly linked lists through per-slot arrays: insert, remove and move are O(1).
 */
export class Grid {
  ox = 0;
  oy = 0;
  /** Cell side. */
  w = 1;
  nx = 1;
  ny = 1;
  head: Int32Array = new Int32Array(1).fill(-1);
  next: Int32Array;
  prev: Int32Array;
  cellOf: Int32Array;

  constructor(slotCapacity: number) {
    this.next = new Int32Array(slotCapacity).fill(-1);
    this.prev = new Int32Array(slotCapacity).fill(-1);
    this.cellOf = new Int32Array(slotCapacity).fill(-1);
  }

  reserve(capacity: number): void {
    if (capacity <= this.next.length) return;
    const cap = Math.max(capacity, this.next.length * 2);
    const grow = (a: Int32Array): Int32Array => {
      const b = new Int32Array(cap).fill(-1);
      b.set(a);
      return b;
    };
    this.next = grow(this.next);
    this.prev = grow(this.prev);
    this.cellOf = grow(this.cellOf);
  }

  /** Reset to an empty grid of nx * ny cells of side w with lower-left corner (ox, oy). */
  reset(ox: number, oy: number, w: number, nx: number, ny: number): void {
    this.ox = ox;
    this.oy = oy;
    this.w = w;
    this.nx = nx;
    this.ny = ny;
    if (this.head.length < nx * ny) this.head = new Int32Array(nx * ny);
    this.head.fill(-1, 0, nx * ny);
    this.cellOf.fill(-1);
  }

  /** Column of x (clamped to the grid: edge columns extend to infinity). */
  column(x: number): number {
    const c = Math.floor((x - this.ox) / this.w);
    return c < 0 ? 0 : c >= this.nx ? this.nx - 1 : c;
  }

  row(y: number): number {
    const c = Math.floor((y - this.oy) / this.w);
    return c < 0 ? 0 : c >= this.ny ? this.ny - 1 : c;
  }

  /** x of the boundary between column c - 1 and column c. */
  boundaryX(c: number): number {
    return this.ox + c * this.w;
  }

  boundaryY(r: number): number {
    return this.oy + r * this.w;
  }

  insert(slot: number, cell: number): void {
    const h = this.head[cell] as number;
    this.next[slot] = h;
    this.prev[slot] = -1;
    if (h >= 0) this.prev[h] = slot;
    this.head[cell] = slot;
    this.cellOf[slot] = cell;
  }

  remove(slot: number): void {
    const cell = this.cellOf[slot] as number;
    if (cell < 0) return;
    const p = this.prev[slot] as number;
    const n = this.next[slot] as number;
    if (p >= 0) this.next[p] = n;
    else this.head[cell] = n;
    if (n >= 0) this.prev[n] = p;
    this.cellOf[slot] = -1;
    this.next[slot] = -1;
    this.prev[slot] = -1;
  }

  move(slot: number, cell: number): void {
    this.remove(slot);
    this.insert(slot, cell);
  }

  /** Deep copy. */
  clone(): Grid {
    const g = new Grid(this.next.length);
    g.ox = this.ox;
    g.oy = this.oy;
    g.w = this.w;
    g.nx = this.nx;
    g.ny = this.ny;
    g.head = this.head.slice();
    g.next = this.next.slice();
    g.prev = this.prev.slice();
    g.cellOf = this.cellOf.slice();
    return g;
  }
}
