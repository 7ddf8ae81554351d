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
 * A few discs far larger than the rest (big bodies, sim/state.ts) are kept out of the cells
 * (cellOf = BIG_CELL) so that the cells stay sized for the others.
 *
 * The outermost rows and columns extend to infinity, so a body leaving the region stays in an edge
 * cell and causes no more crossing events (a disc flying away for ever costs nothing). Cells are
 * doubly linked lists through per-slot arrays: insert, remove and move are O(1). `cellRadius` picks
 * the radius the cells are sized for, and so which bodies are big.
 */
import { GRID_BIG_BODIES_MAX, GRID_BIG_RATIO } from "../tolerances.js";

/** cellOf of a body too large for the cells: kept out of them, tested against every body (state.ts). */
export const BIG_CELL = -2;

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

  /**
   * Static obstacles per cell in compressed rows: the codes of cell c are
   * obstList[obstStart[c] .. obstStart[c + 1]). Codes: i >= 0 is segment i of the world's line
   * list, -(i + 1) is point i. Filled by `setObstacles`.
   */
  obstStart: Int32Array = new Int32Array(2);
  obstList: Int32Array = new Int32Array(0);

  /** Fill the per-cell obstacle lists from (cell, code) pairs. */
  setObstacles(pairs: number[]): void {
    const nc = this.nx * this.ny;
    const start = new Int32Array(nc + 1);
    for (let i = 0; i < pairs.length; i += 2)
      start[(pairs[i] as number) + 1] = (start[(pairs[i] as number) + 1] as number) + 1;
    for (let c = 0; c < nc; c++) start[c + 1] = (start[c + 1] as number) + (start[c] as number);
    const fill = start.slice(0, nc);
    const list = new Int32Array(pairs.length / 2);
    for (let i = 0; i < pairs.length; i += 2) {
      const c = pairs[i] as number;
      list[fill[c] as number] = pairs[i + 1] as number;
      fill[c] = (fill[c] as number) + 1;
    }
    this.obstStart = start;
    this.obstList = list;
  }

  /** Cell rectangle [x0, x1] x [y0, y1]; edge cells extend to infinity. */
  cellRect(cx: number, cy: number): [number, number, number, number] {
    const inf = Number.POSITIVE_INFINITY;
    return [
      cx === 0 ? -inf : this.boundaryX(cx),
      cx === this.nx - 1 ? inf : this.boundaryX(cx + 1),
      cy === 0 ? -inf : this.boundaryY(cy),
      cy === this.ny - 1 ? inf : this.boundaryY(cy + 1),
    ];
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
    g.obstStart = this.obstStart;
    g.obstList = this.obstList;
    return g;
  }
}

/**
 * Radius the grid's cells are made for: the largest radius once the few largest are left out, when
 * they are more than GRID_BIG_RATIO times the (GRID_BIG_BODIES_MAX + 1)-th largest (they become big
 * bodies); else the largest radius.
 */
export function cellRadius(radii: number[]): number {
  const sorted = radii.slice().sort((a, b) => b - a);
  if (sorted.length <= GRID_BIG_BODIES_MAX) return sorted[0] ?? 0;
  const limit = GRID_BIG_RATIO * (sorted[GRID_BIG_BODIES_MAX] as number);
  for (const r of sorted) if (r <= limit) return r;
  return sorted[0] as number;
}
