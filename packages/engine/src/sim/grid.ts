/**
 * Broad phase: nested uniform grids ("levels") over the region the bodies occupy, with
 * cell-crossing events.
 *
 * Why a grid with crossing events (and not swept boxes): discs have bounded radii, so with a cell
 * side w >= 2 * maxR two discs in contact are always in the same or adjacent cells; a body's
 * neighbourhood changes only when its centre crosses a cell boundary, which is itself an exact
 * event (a root of a degree <= 2 polynomial). Each event then costs O(1) pair tests plus O(1)
 * expected in the event queue, whatever N is, for discs of similar sizes (a disc in a coarser
 * level tests the finer discs under its 3x3 block, or all of a finer level when they are fewer
 * than the cells there). Swept boxes need a time bound per box and
 * re-insertion when it expires, which costs more per event for the dilute gases this engine is
 * built for.
 *
 * Levels (for scenes of very different radii): level k has cells of side w * 2^k over the same
 * origin, so level k's column of a point is its level-0 column >> k and every level-k boundary is
 * also a level-0 boundary. Each body is registered in one level, the finest whose cells fit it
 * (`levelFor`). A pair is a candidate when the two bodies' cells are adjacent at the coarser of
 * their two levels: a body of level k is tested against the bodies of its own and coarser levels in
 * the 3x3 cells around it there, and against finer bodies in the finer cells under its own 3x3
 * block. A body's cell at a coarser level can only change when it crosses a boundary of its own
 * level, which is an event already, so adjacency stays exact. The top level may be a single cell
 * (everything adjacent), which takes any radius. The levels always go up to it; while only level 0
 * holds bodies (`flat`), the scans are those of a plain grid.
 *
 * The outermost rows and columns of every level extend to infinity, so a body leaving the region
 * stays in an edge cell and causes no more crossing events (a disc flying away for ever costs
 * nothing). Cells are doubly linked lists through per-slot arrays shared by all levels (a body is
 * in one cell): insert, remove and move are O(1). Cell indices are global: level k's cells are
 * base[k] ... base[k] + nxOf[k] * nyOf[k] - 1, row by row.
 */

import { mulPow2 } from "../roots/pow2.js";
import { GRID_CELL_MARGIN } from "../tolerances.js";
import { buildLevel, levelBuilt, setObstacles } from "./gridObstacles.js";

const INF = Number.POSITIVE_INFINITY;

/** Most levels a grid has: cells 2^(GRID_LEVELS_MAX - 1) times the finest ones reach any region. */
const GRID_LEVELS_MAX = 31;

export class Grid {
  ox = 0;
  oy = 0;
  /** Cell side at level 0. */
  w = 1;
  /** Columns and rows at level 0. */
  nx = 1;
  ny = 1;
  /** Number of levels (>= 1). */
  levels = 1;
  /** Per level: columns, rows, first global cell index, largest radius it fits, bodies in it. */
  nxOf: Int32Array = new Int32Array([1]);
  nyOf: Int32Array = new Int32Array([1]);
  base: Int32Array = new Int32Array([0, 1]);
  fitR: Float64Array = new Float64Array([INF]);
  count: Int32Array = new Int32Array(1);
  /** Levels that hold at least one body, ascending (the scans visit only these). */
  occupied: number[] = [];
  /** Whether no level but level 0 holds a body (the scans of a plain grid then suffice). */
  flat = true;
  /**
   * The bodies of each level, in no particular order, and each slot's place in its level's list: a
   * coarse disc near more finer cells than the finer level has bodies tests those bodies instead.
   */
  members: number[][] = [[]];
  // `declare`: set in the constructor, never undefined, so V8 knows the array type (bodyStore.ts).
  declare memberPos: Int32Array;
  head: Int32Array = new Int32Array(1).fill(-1);
  declare next: Int32Array;
  declare prev: Int32Array;
  /** Global cell of each slot (-1: not registered), and its level. */
  declare cellOf: Int32Array;
  declare levelOf: Int8Array;

  constructor(slotCapacity: number) {
    this.next = new Int32Array(slotCapacity).fill(-1);
    this.prev = new Int32Array(slotCapacity).fill(-1);
    this.cellOf = new Int32Array(slotCapacity).fill(-1);
    this.levelOf = new Int8Array(slotCapacity);
    this.memberPos = new Int32Array(slotCapacity);
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
    const lv = new Int8Array(cap);
    lv.set(this.levelOf);
    this.levelOf = lv;
    const mp = new Int32Array(cap);
    mp.set(this.memberPos);
    this.memberPos = mp;
  }

  /**
   * Reset to an empty grid with level-0 cells of side w, nx * ny of them, lower-left corner
   * (ox, oy), and coarser levels up to one of a single cell, which fits any radius (so a disc of any
   * size has a level without a rebuild). Level 0 fits `sizedFor`, the radius w was computed from (w
   * is at least 2 * GRID_CELL_MARGIN times it, up to rounding). nx = ny = 1 gives one cell for
   * everything.
   */
  reset(ox: number, oy: number, w: number, nx: number, ny: number, sizedFor = 0): void {
    this.ox = ox;
    this.oy = oy;
    this.w = w;
    // Whole numbers below 2^31 (cell counts): stored as small integers, so that the hot path's cell
    // arithmetic runs in integers (a field that once held a double stays a boxed double).
    this.nx = nx | 0;
    this.ny = ny | 0;
    const nxOf: number[] = [];
    const nyOf: number[] = [];
    const fit: number[] = [];
    for (let k = 0; k < GRID_LEVELS_MAX; k++) {
      const cx = ((nx - 1) >> k) + 1;
      const cy = ((ny - 1) >> k) + 1;
      const single = cx === 1 && cy === 1;
      nxOf.push(cx);
      nyOf.push(cy);
      // Level 0 fits the radius its side was computed from, whatever the rounding of w / (2 margin).
      fit.push(single ? INF : Math.max(mulPow2(w, k) / (2 * GRID_CELL_MARGIN), k === 0 ? sizedFor : 0));
      if (single) break;
    }
    const levels = nxOf.length;
    this.levels = levels;
    this.nxOf = Int32Array.from(nxOf);
    this.nyOf = Int32Array.from(nyOf);
    this.fitR = Float64Array.from(fit);
    this.base = new Int32Array(levels + 1);
    for (let k = 0; k < levels; k++)
      this.base[k + 1] = (this.base[k] as number) + (nxOf[k] as number) * (nyOf[k] as number);
    const cells = this.base[levels] as number;
    // Reused while large enough; given back when a rebuild needs far fewer cells (a roomy layout
    // while a scene is built can be many times the final one: 180,000 cells for 40,000 at N = 10⁴).
    if (this.head.length < cells || this.head.length > 4 * cells + 1024) this.head = new Int32Array(cells);
    this.head.fill(-1, 0, cells);
    this.count = new Int32Array(levels);
    this.members = nxOf.map(() => []);
    this.occupied = [];
    // No obstacles until setObstacles (which a rebuild calls after placing the bodies).
    setObstacles(this, []);
    this.obstBuilt.fill(1);
    this.flat = true;
    this.cellOf.fill(-1);
  }

  /** Finest level whose cells fit a disc of radius r (the top level, a single cell, fits any). */
  levelFor(r: number): number {
    let k = 0;
    while (k < this.levels - 1 && r > (this.fitR[k] as number)) k++;
    return k;
  }

  /** Where `locate` puts a slot's level and its column and row in that level. */
  readonly at: Int32Array = new Int32Array(3);

  /** Set `at` to slot s's level, column and row (s must be registered). */
  locate(slot: number): void {
    const k = this.levelOf[slot] as number;
    const nxk = this.nxOf[k] as number;
    const local = (this.cellOf[slot] as number) - (this.base[k] as number);
    const cx = local % nxk;
    this.at[0] = k;
    this.at[1] = cx;
    this.at[2] = (local - cx) / nxk;
  }

  /** Global index of the level-k cell holding the level-0 cell (cx, cy). */
  cellAt(k: number, cx: number, cy: number): number {
    return (this.base[k] as number) + (cy >> k) * (this.nxOf[k] as number) + (cx >> k);
  }

  /** Register slot s in level k's cell `cell` (global index). */
  enter(slot: number, k: number, cell: number): void {
    this.levelOf[slot] = k;
    this.insert(slot, cell);
    const list = this.members[k] as number[];
    this.memberPos[slot] = list.length;
    list.push(slot);
    const c = this.count[k] as number;
    this.count[k] = c + 1;
    if (c === 0) {
      this.setOccupied([...this.occupied, k].sort((a, b) => a - b));
      if (this.obstBuilt[k] === 0) buildLevel(this, k);
    }
  }

  /** Take slot s out of the grid (nothing if it is not registered). */
  leave(slot: number): void {
    if ((this.cellOf[slot] as number) < 0) return;
    const k = this.levelOf[slot] as number;
    this.remove(slot);
    const list = this.members[k] as number[];
    const last = list.pop() as number;
    if (last !== slot) {
      const at = this.memberPos[slot] as number;
      list[at] = last;
      this.memberPos[last] = at;
    }
    const c = (this.count[k] as number) - 1;
    this.count[k] = c;
    if (c === 0) this.setOccupied(this.occupied.filter((j) => j !== k));
  }

  private setOccupied(levels: number[]): void {
    this.occupied = levels;
    this.flat = levels.length === 0 || (levels.length === 1 && levels[0] === 0);
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

  /** remove then insert, in one body (small enough for V8 to inline into a crossing). */
  move(slot: number, cell: number): void {
    const old = this.cellOf[slot] as number;
    if (old >= 0) {
      const p = this.prev[slot] as number;
      const n = this.next[slot] as number;
      if (p >= 0) this.next[p] = n;
      else this.head[old] = n;
      if (n >= 0) this.prev[n] = p;
    }
    const h = this.head[cell] as number;
    this.next[slot] = h;
    this.prev[slot] = -1;
    if (h >= 0) this.prev[h] = slot;
    this.head[cell] = slot;
    this.cellOf[slot] = cell;
  }

  /**
   * Static obstacles per cell (gridObstacles.ts): the codes of cell c are
   * obstList[obstStart[c] .. obstEnd[c]), with room up to obstCap[c]. Codes: i >= 0 is segment i of
   * the world's line list, -(i + 1) is point i. Built for level 0 and the levels holding bodies (only
   * a body scans its own level's obstacles); a level gets its rows when a body first enters it.
   * obstStart has one entry more than there are cells; while the rows are packed (`obstPacked`),
   * obstEnd and obstCap are views of it from its second entry (no memory of their own).
   */
  obstStart: Int32Array = new Int32Array(2);
  obstEnd: Int32Array = this.obstStart.subarray(1);
  obstCap: Int32Array = this.obstStart.subarray(1);
  obstList: Int32Array = new Int32Array(0);
  /** Codes and room laid out in obstList, and codes registered (gridObstacles.ts). */
  obstTail = 0;
  obstLive = 0;
  /** Whether the rows lie back to back in cell order, each ending where the next begins (gridObstacles.ts). */
  obstPacked = true;
  /**
   * One bit per cell, set when its row is not empty: 1/32 of obstStart's size, so the scans of a
   * large grid whose cells are mostly empty of obstacles read a few cached words, not obstStart.
   */
  obstBits: Int32Array = new Int32Array(1);
  /**
   * One bit per level-0 cell, set when the cell or one of its eight neighbours lists obstacles: a
   * plain grid's 3 x 3 scan (and a crossing's strip, inside the new cell's 3 x 3) reads this one
   * bit and skips the obstacle bits of all its cells when it is clear, as in most cells of a gas.
   * Kept exact through the obstacle edits (gridObstacles.ts).
   */
  obstNear: Int32Array = new Int32Array(1);
  /** The levels whose rows are built, and whether a copy shares the rows (copy on write). */
  obstBuilt: Uint8Array = new Uint8Array(1).fill(1);
  obstShared = false;

  /** Set the obstacles from level-0 (cell, code) pairs (gridObstacles.ts). */
  setObstacles(level0: number[]): void {
    setObstacles(this, level0);
  }

  /** Whether level k's obstacle rows are built (the others read as empty). */
  obstaclesBuilt(k: number): boolean {
    return levelBuilt(this, k);
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
    g.levels = this.levels;
    g.nxOf = this.nxOf;
    g.nyOf = this.nyOf;
    g.base = this.base;
    g.fitR = this.fitR;
    g.count = this.count.slice();
    g.occupied = this.occupied;
    g.flat = this.flat;
    g.head = this.head.slice();
    g.next = this.next.slice();
    g.prev = this.prev.slice();
    g.cellOf = this.cellOf.slice();
    g.levelOf = this.levelOf.slice();
    g.members = this.members.map((m) => m.slice());
    g.memberPos = this.memberPos.slice();
    g.obstStart = this.obstStart;
    g.obstEnd = this.obstEnd;
    g.obstCap = this.obstCap;
    g.obstList = this.obstList;
    g.obstTail = this.obstTail;
    g.obstLive = this.obstLive;
    g.obstPacked = this.obstPacked;
    g.obstBits = this.obstBits;
    g.obstNear = this.obstNear;
    g.obstBuilt = this.obstBuilt.slice();
    g.obstShared = true;
    this.obstShared = true;
    return g;
  }
}
