/**
 * The grid's obstacle rows: per cell, the codes of the segments and points registered in it (i >= 0:
 * line i of the World's list, -(i + 1): point i), for level 0 and the levels whose rows are built
 * (level 0 and the levels holding bodies, as a body scans only its own level's rows; a level gets
 * its rows when a body first enters it, so a rebuild does not pay for the many empty levels up to
 * the single top cell). A coarser cell lists
 * what its level-0 cells list, each code once. The order within a row is no contract: predictions
 * break ties between obstacles by id. Grid (grid.ts) extends this class; the edits in place are in
 * gridObstacleEdits.ts.
 *
 * All rows share one Int32Array: cell c's codes are obstList[obstStart[c] .. obstEnd[c]), with room
 * up to obstCap[c]. A rebuild lays them out back to back in cell order (`obstPacked`): then each
 * row ends where the next begins, and obstEnd and obstCap are views of obstStart from its second
 * entry (obstStart has one entry more than there are cells), which cost no memory: two arrays of
 * one entry per cell are 8 bytes per cell, about 33 bytes per body in a gas, which would be paid
 * by every World while only obstacle edits use them. The first edit in place gives them arrays of
 * their own (`editInPlace`). obstBits has one bit per cell whose row is not empty (the scans read a
 * few cached words on a large, mostly empty grid), and obstNear one bit per level-0 cell whose 3 x 3
 * holds a cell with a row (a plain grid's scan reads that one bit), both kept exact by every edit.
 * A copy of the grid shares the rows until either side edits them (copy on write).
 */
import { GridLayout } from "./gridLayout.js";

export class GridObstacles extends GridLayout {
  /** Row starts, one entry per cell and one more (see the module's comment). */
  obstStart: Int32Array = new Int32Array(2);
  /** Row ends and rooms: views of obstStart while the rows are packed, arrays of their own after. */
  obstEnd: Int32Array = this.obstStart.subarray(1);
  obstCap: Int32Array = this.obstStart.subarray(1);
  obstList: Int32Array = new Int32Array(0);
  /** Codes and room laid out in obstList, and codes registered. */
  obstTail = 0;
  obstLive = 0;
  /** Whether the rows lie back to back in cell order, each ending where the next begins. */
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
   */
  obstNear: Int32Array = new Int32Array(1);
  /** The levels whose rows are built, and whether a copy shares the rows (copy on write). */
  obstBuilt: Uint8Array = new Uint8Array(1).fill(1);
  obstShared = false;

  /** Whether level k's obstacle rows are built (the others read as empty). */
  obstaclesBuilt(k: number): boolean {
    return this.obstBuilt[k] === 1;
  }

  /** Let the copy `g` share these rows until either side edits them. */
  protected shareObstaclesWith(g: GridObstacles): void {
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
  }
}

/**
 * Set the rows from level-0 (cell, code) pairs (each cell once per code), packed, for level 0 and
 * the levels `occupied`; the other levels get theirs when a body enters (buildLevel).
 */
export function setObstacles(g: GridObstacles, level0: readonly number[], occupied: readonly number[]): void {
  g.obstBuilt = new Uint8Array(g.levels);
  g.obstBuilt[0] = 1;
  for (const k of occupied) g.obstBuilt[k] = 1;
  const pairs = level0.slice();
  for (let k = 1; k < g.levels; k++) if (g.obstBuilt[k] === 1) coarsePairs(g, k, level0, pairs);
  layOutPacked(g, pairs);
  g.obstNear = new Int32Array(((g.nx * g.ny) >> 5) + 1);
  for (let c = 0; c < g.nx * g.ny; c++) if (hasRow(g, c)) markNear(g, c);
}

/** Build level k's rows (a body entered it for the first time), from level 0's. */
export function buildLevel(g: GridObstacles, k: number): void {
  if (g.obstBuilt[k] === 1) return;
  own(g);
  g.obstBuilt[k] = 1;
  const level0: number[] = [];
  for (let c = 0; c < g.nx * g.ny; c++)
    for (let i = g.obstStart[c] as number; i < (g.obstEnd[c] as number); i++)
      level0.push(c, g.obstList[i] as number);
  const pairs: number[] = [];
  coarsePairs(g, k, level0, pairs);
  if (!g.obstPacked) {
    appendRows(g, pairs, g.base[k] as number, g.base[k + 1] as number);
    return;
  }
  // Packed: lay every row out again with the new level's (O(cells + codes), as the pass above).
  const all: number[] = [];
  for (let c = 0; c < (g.base[g.levels] as number); c++)
    for (let i = g.obstStart[c] as number; i < (g.obstEnd[c] as number); i++)
      all.push(c, g.obstList[i] as number);
  for (const p of pairs) all.push(p);
  layOutPacked(g, all);
}

/** Give the rows their own ends and rooms, so that they can grow and shrink in place (and stop sharing them). */
export function editInPlace(g: GridObstacles): void {
  own(g);
  if (!g.obstPacked) return;
  g.obstEnd = g.obstStart.slice(1);
  g.obstCap = g.obstStart.slice(1);
  g.obstPacked = false;
}

/** Stop sharing the rows with a copy of the grid before editing them. */
export function own(g: GridObstacles): void {
  if (!g.obstShared) return;
  g.obstStart = g.obstStart.slice();
  if (g.obstPacked) {
    g.obstEnd = g.obstStart.subarray(1);
    g.obstCap = g.obstStart.subarray(1);
  } else {
    g.obstEnd = g.obstEnd.slice();
    g.obstCap = g.obstCap.slice();
  }
  g.obstList = g.obstList.slice();
  g.obstBits = g.obstBits.slice();
  g.obstNear = g.obstNear.slice();
  g.obstShared = false;
}

export function hasRow(g: GridObstacles, cell: number): boolean {
  return ((g.obstBits[cell >> 5] as number) & (1 << (cell & 31))) !== 0;
}

/** The level-0 cells of the 3 x 3 around level-0 cell c (clipped to the grid), each visited. */
export function forEachAround(g: GridObstacles, c: number, visit: (cell: number) => void): void {
  const nx = g.nx;
  const cy = (c / nx) | 0;
  const cx = c - cy * nx;
  for (let y = Math.max(0, cy - 1); y <= Math.min(g.ny - 1, cy + 1); y++)
    for (let x = Math.max(0, cx - 1); x <= Math.min(nx - 1, cx + 1); x++) visit(y * nx + x);
}

/** Level-0 cell c has a row now: its 3 x 3 is near obstacles. */
export function markNear(g: GridObstacles, c: number): void {
  forEachAround(g, c, (n) => {
    g.obstNear[n >> 5] = (g.obstNear[n >> 5] as number) | (1 << (n & 31));
  });
}

/** Make room for `n` more codes at the end of the list. */
export function reserveList(g: GridObstacles, n: number): void {
  if (g.obstTail + n <= g.obstList.length) return;
  const list = new Int32Array(Math.max(2 * g.obstList.length, g.obstTail + n));
  list.set(g.obstList.subarray(0, g.obstTail));
  g.obstList = list;
}

/** Append to `out` level k's (cell, code) pairs over the level-0 pairs `level0`, each once. */
function coarsePairs(g: GridObstacles, k: number, level0: readonly number[], out: number[]): void {
  const seen = new Set<number>();
  const cells = (g.base[k + 1] as number) - (g.base[k] as number);
  for (let i = 0; i < level0.length; i += 2) {
    const c = level0[i] as number;
    const cx = c % g.nx;
    const cell = g.cellAt(k, cx, (c - cx) / g.nx);
    const code = level0[i + 1] as number;
    // Codes run from -(points) to lines - 1; key each (cell, code) pair uniquely.
    const key = cell - (g.base[k] as number) + cells * (code + level0.length);
    if (seen.has(key)) continue;
    seen.add(key);
    out.push(cell, code);
  }
}

/**
 * Lay out every row, packed in cell order, from the (cell, code) pairs (each cell's codes in the
 * pairs' order), with new arrays: row starts (ends and rooms their views), list and bits.
 */
function layOutPacked(g: GridObstacles, pairs: readonly number[]): void {
  const nc = g.base[g.levels] as number;
  const start = new Int32Array(nc + 1);
  for (let i = 0; i < pairs.length; i += 2) {
    const c = (pairs[i] as number) + 1;
    start[c] = (start[c] as number) + 1;
  }
  for (let c = 0; c < nc; c++) start[c + 1] = (start[c + 1] as number) + (start[c] as number);
  const codes = pairs.length / 2;
  const list = new Int32Array(Math.max(16, codes));
  const bits = new Int32Array((nc >> 5) + 1);
  // Fill each row from its start; the row's end (the next start) is filled last, so `fill[c]` runs ahead.
  const fill = start.slice(0, nc);
  for (let i = 0; i < pairs.length; i += 2) {
    const cell = pairs[i] as number;
    const at = fill[cell] as number;
    list[at] = pairs[i + 1] as number;
    fill[cell] = at + 1;
    bits[cell >> 5] = (bits[cell >> 5] as number) | (1 << (cell & 31));
  }
  g.obstStart = start;
  g.obstEnd = start.subarray(1);
  g.obstCap = start.subarray(1);
  g.obstList = list;
  g.obstBits = bits;
  g.obstTail = codes;
  g.obstLive = codes;
  g.obstPacked = true;
  g.obstShared = false;
}

/**
 * Rows not packed: lay out new rows at the end of the list, in cell order, without room to spare,
 * for the (cell, code) pairs, whose cells lie in [lo, hi) and have empty rows.
 */
function appendRows(g: GridObstacles, pairs: readonly number[], lo: number, hi: number): void {
  const counts = new Int32Array(hi - lo);
  for (let i = 0; i < pairs.length; i += 2) {
    const c = (pairs[i] as number) - lo;
    counts[c] = (counts[c] as number) + 1;
  }
  reserveList(g, pairs.length / 2);
  let tail = g.obstTail;
  for (let c = lo; c < hi; c++) {
    const n = counts[c - lo] as number;
    if (n === 0) continue;
    g.obstStart[c] = tail;
    g.obstEnd[c] = tail;
    tail += n;
    g.obstCap[c] = tail;
  }
  g.obstTail = tail;
  for (let i = 0; i < pairs.length; i += 2) {
    const cell = pairs[i] as number;
    const end = g.obstEnd[cell] as number;
    g.obstList[end] = pairs[i + 1] as number;
    g.obstEnd[cell] = end + 1;
    g.obstBits[cell >> 5] = (g.obstBits[cell >> 5] as number) | (1 << (cell & 31));
  }
  g.obstLive += pairs.length / 2;
}
