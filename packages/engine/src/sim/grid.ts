/**
 * Broad phase: nested uniform grids ("levels") over the region the bodies occupy, with
 * cell-crossing events; this class holds the bodies in the cells. The levels' geometry is
 * GridLayout's (gridLayout.ts), the obstacles listed per cell GridObstacles' (gridObstacles.ts):
 * Grid extends both, so a grid is one object whose fields the hot path reads directly.
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
 * Each body is registered in one level, the finest whose cells fit it (`levelFor`). A pair is a
 * candidate when the two bodies' cells are adjacent at the coarser of their two levels: a body of
 * level k is tested against the bodies of its own and coarser levels in the 3x3 cells around it
 * there, and against finer bodies in the finer cells under its own 3x3 block. A body's cell at a
 * coarser level can only change when it crosses a boundary of its own level, which is an event
 * already, so adjacency stays exact. While only level 0 holds bodies (`flat`), the scans are those
 * of a plain grid.
 *
 * Cells are doubly linked lists through per-slot arrays shared by all levels (a body is in one
 * cell): insert, remove and move are O(1).
 */

import { buildLevel, GridObstacles, setObstacles } from "./gridObstacles.js";

export class Grid extends GridObstacles {
  /** Per level: bodies in it. */
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
  /** Where `locate` puts a slot's level and its column and row in that level. */
  readonly at: Int32Array = new Int32Array(3);

  constructor(slotCapacity: number) {
    super();
    this.next = new Int32Array(slotCapacity).fill(-1);
    this.prev = new Int32Array(slotCapacity).fill(-1);
    this.cellOf = new Int32Array(slotCapacity).fill(-1);
    this.levelOf = new Int8Array(slotCapacity);
    this.memberPos = new Int32Array(slotCapacity);
  }

  /** Number of slots it can hold (0 .. slotCapacity - 1). */
  get slotCapacity(): number {
    return this.next.length;
  }

  /**
   * Set the slot range to exactly 0 .. capacity - 1 (the World's body store's capacity), keeping
   * every registered slot where it is: a registered slot must be below `capacity` (a RangeError
   * otherwise, and nothing changes).
   */
  resize(capacity: number): void {
    for (let s = capacity; s < this.cellOf.length; s++)
      if ((this.cellOf[s] as number) >= 0)
        throw new RangeError(`grid: slot ${s} is registered, beyond the new range ${capacity}`);
    const keep = Math.min(capacity, this.next.length);
    const sized = (a: Int32Array, fill: number): Int32Array => {
      const b = new Int32Array(capacity);
      if (fill !== 0) b.fill(fill);
      b.set(a.subarray(0, keep));
      return b;
    };
    this.next = sized(this.next, -1);
    this.prev = sized(this.prev, -1);
    this.cellOf = sized(this.cellOf, -1);
    this.memberPos = sized(this.memberPos, 0);
    const lv = new Int8Array(capacity);
    lv.set(this.levelOf.subarray(0, keep));
    this.levelOf = lv;
  }

  /**
   * Reset to an empty grid laid out as GridLayout.layOut says (level-0 cells of side w, nx * ny of
   * them, lower-left corner (ox, oy), coarser levels up to a single cell; level 0 fits `sizedFor`),
   * with no obstacles until setObstacles (which a rebuild calls after placing the bodies).
   */
  reset(ox: number, oy: number, w: number, nx: number, ny: number, sizedFor = 0): void {
    this.layOut(ox, oy, w, nx, ny, sizedFor);
    const levels = this.levels;
    const cells = this.base[levels] as number;
    // Reused while large enough; given back when a rebuild needs far fewer cells (a roomy layout
    // while a scene is built can be many times the final one: 180,000 cells for 40,000 at N = 10⁴).
    if (this.head.length < cells || this.head.length > 4 * cells + 1024) this.head = new Int32Array(cells);
    this.head.fill(-1, 0, cells);
    this.count = new Int32Array(levels);
    this.members = [];
    for (let k = 0; k < levels; k++) this.members.push([]);
    this.occupied = [];
    setObstacles(this, [], []);
    this.obstBuilt.fill(1);
    this.flat = true;
    this.cellOf.fill(-1);
  }

  /** Set the obstacles from level-0 (cell, code) pairs, for level 0 and the levels holding bodies (gridObstacles.ts). */
  setObstacles(level0: number[]): void {
    setObstacles(this, level0, this.occupied);
  }

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

  /** Deep copy (the obstacle rows shared until either side edits them). */
  clone(): Grid {
    const g = new Grid(this.next.length);
    this.copyLayoutInto(g);
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
    this.shareObstaclesWith(g);
    return g;
  }
}
