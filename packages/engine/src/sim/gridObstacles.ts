/**
 * The grid's obstacle rows (grid.ts's obst* fields): per cell, the codes of the segments and points
 * registered in it (i >= 0: line i of the World's list, -(i + 1): point i), for level 0 and the
 * levels whose rows are built (level 0 and the levels holding bodies; a level gets its rows when a
 * body first enters it, so a rebuild does not pay for the many empty levels up to the single top
 * cell). A coarser cell lists what its level-0 cells list, each code once. The order within a row
 * is no contract: predictions break ties between obstacles by id.
 *
 * All rows share one Int32Array: cell c's codes are obstList[obstStart[c] .. obstEnd[c]), with room
 * up to obstCap[c]. A rebuild lays them out back to back in cell order (`obstPacked`): then each
 * row ends where the next begins, and obstEnd and obstCap are views of obstStart from its second
 * entry (obstStart has one entry more than there are cells), which cost no memory: two arrays of
 * one entry per cell are 8 bytes per cell, about 33 bytes per body in a gas, which would be paid
 * by every World while only obstacle edits use them. The first edit in place gives them arrays of
 * their own (`editInPlace`). A row that outgrows its room moves to the end of the list with twice
 * the room (the list grows by doubling, and is packed again when the rooms left behind outnumber
 * the codes), so adding or removing one obstacle costs the cells it covers at each built level,
 * not the grid: the World's obstacle edits (obstacleUpkeep.ts) keep the grid's layout this way.
 * obstBits has one bit per cell whose row is not empty (the scans read a few cached words on a
 * large, mostly empty grid), and obstNear one bit per level-0 cell whose 3 x 3 holds a cell with a
 * row (a plain grid's scan reads that one bit), both kept exact by every edit. A copy of the grid
 * shares the rows until either side edits them (copy on write).
 */
import type { Grid } from "./grid.js";

/** Fewest codes of room a row gets when it first grows. */
const ROW_ROOM_MIN = 4;

/**
 * Set the rows from level-0 (cell, code) pairs (each cell once per code), packed, for level 0 and
 * the levels holding bodies; the other levels get theirs when a body enters (buildLevel).
 */
export function setObstacles(g: Grid, level0: readonly number[]): void {
  g.obstBuilt = new Uint8Array(g.levels);
  g.obstBuilt[0] = 1;
  for (const k of g.occupied) g.obstBuilt[k] = 1;
  const pairs = level0.slice();
  for (let k = 1; k < g.levels; k++) if (g.obstBuilt[k] === 1) coarsePairs(g, k, level0, pairs);
  layOutPacked(g, pairs);
  g.obstNear = new Int32Array(((g.nx * g.ny) >> 5) + 1);
  for (let c = 0; c < g.nx * g.ny; c++) if (hasRow(g, c)) markNear(g, c);
}

function hasRow(g: Grid, cell: number): boolean {
  return ((g.obstBits[cell >> 5] as number) & (1 << (cell & 31))) !== 0;
}

/** The level-0 cells of the 3 x 3 around level-0 cell c (clipped to the grid), each visited. */
function forEachAround(g: Grid, c: number, visit: (cell: number) => void): void {
  const nx = g.nx;
  const cy = (c / nx) | 0;
  const cx = c - cy * nx;
  for (let y = Math.max(0, cy - 1); y <= Math.min(g.ny - 1, cy + 1); y++)
    for (let x = Math.max(0, cx - 1); x <= Math.min(nx - 1, cx + 1); x++) visit(y * nx + x);
}

/** Level-0 cell c has a row now: its 3 x 3 is near obstacles. */
function markNear(g: Grid, c: number): void {
  forEachAround(g, c, (n) => {
    g.obstNear[n >> 5] = (g.obstNear[n >> 5] as number) | (1 << (n & 31));
  });
}

/** Level-0 cell c's row became empty: each cell of its 3 x 3 is near obstacles only if a cell of its own 3 x 3 has a row. */
function unmarkNear(g: Grid, c: number): void {
  forEachAround(g, c, (n) => {
    let near = false;
    forEachAround(g, n, (m) => {
      near ||= hasRow(g, m);
    });
    if (!near) g.obstNear[n >> 5] = (g.obstNear[n >> 5] as number) & ~(1 << (n & 31));
  });
}

/** Whether level k's rows are built (the others read as empty). */
export function levelBuilt(g: Grid, k: number): boolean {
  return g.obstBuilt[k] === 1;
}

/** Build level k's rows (a body entered it for the first time), from level 0's. */
export function buildLevel(g: Grid, k: number): void {
  if (g.obstBuilt[k] === 1) return;
  own(g);
  g.obstBuilt[k] = 1;
  const level0: number[] = [];
  const cells0 = g.nx * g.ny;
  for (let c = 0; c < cells0; c++)
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
function editInPlace(g: Grid): void {
  own(g);
  if (!g.obstPacked) return;
  g.obstEnd = g.obstStart.slice(1);
  g.obstCap = g.obstStart.slice(1);
  g.obstPacked = false;
}

/** Register obstacle `code` in the level-0 cells `cells` (distinct) and their cells at every built level. */
export function addObstacle(g: Grid, code: number, cells: readonly number[]): void {
  editInPlace(g);
  forEachCell(g, cells, (cell) => insert(g, cell, code));
}

/** Take obstacle `code`, registered in the level-0 cells `cells` (as addObstacle or setObstacles put it), out of every row. */
export function removeObstacle(g: Grid, code: number, cells: readonly number[]): void {
  editInPlace(g);
  forEachCell(g, cells, (cell) => remove(g, cell, code));
}

/**
 * The World's list dropped line `line` (or, with `line` undefined, point `point`) and closed the
 * gap: renumber the codes after it, one pass over the list of codes (the rows stay where they are).
 */
export function renumberAfterRemoval(g: Grid, line: number | undefined, point = 0): void {
  own(g);
  const list = g.obstList;
  const tail = g.obstTail;
  if (line !== undefined) {
    for (let i = 0; i < tail; i++) if ((list[i] as number) > line) list[i] = (list[i] as number) - 1;
  } else {
    const code = -(point + 1);
    for (let i = 0; i < tail; i++) if ((list[i] as number) < code) list[i] = (list[i] as number) + 1;
  }
}

/** The level-0 cells `cells` and, at each other built level, the cells over them (each once). */
function forEachCell(g: Grid, cells: readonly number[], visit: (cell: number) => void): void {
  for (const c of cells) visit(c);
  for (let k = 1; k < g.levels; k++) {
    if (g.obstBuilt[k] !== 1) continue;
    const seen = new Set<number>();
    for (const c of cells) {
      const cx = c % g.nx;
      const cell = g.cellAt(k, cx, (c - cx) / g.nx);
      if (seen.has(cell)) continue;
      seen.add(cell);
      visit(cell);
    }
  }
}

/** Append to `out` level k's (cell, code) pairs over the level-0 pairs `level0`, each once. */
function coarsePairs(g: Grid, k: number, level0: readonly number[], out: number[]): void {
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
function layOutPacked(g: Grid, pairs: readonly number[]): void {
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
function appendRows(g: Grid, pairs: readonly number[], lo: number, hi: number): void {
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

function insert(g: Grid, cell: number, code: number): void {
  if (g.obstEnd[cell] === g.obstCap[cell]) moveRow(g, cell);
  const end = g.obstEnd[cell] as number;
  g.obstList[end] = code;
  g.obstEnd[cell] = end + 1;
  g.obstBits[cell >> 5] = (g.obstBits[cell >> 5] as number) | (1 << (cell & 31));
  if (end === (g.obstStart[cell] as number) && cell < g.nx * g.ny) markNear(g, cell);
  g.obstLive++;
}

function remove(g: Grid, cell: number, code: number): void {
  const start = g.obstStart[cell] as number;
  const end = g.obstEnd[cell] as number;
  for (let i = start; i < end; i++) {
    if (g.obstList[i] !== code) continue;
    g.obstList[i] = g.obstList[end - 1] as number;
    g.obstEnd[cell] = end - 1;
    if (end - 1 === start) {
      g.obstBits[cell >> 5] = (g.obstBits[cell >> 5] as number) & ~(1 << (cell & 31));
      if (cell < g.nx * g.ny) unmarkNear(g, cell);
    }
    g.obstLive--;
    return;
  }
  throw new Error(`grid rows: obstacle ${code} is not registered in cell ${cell}`);
}

/** Move cell's full row to the end of the list with twice its room. */
function moveRow(g: Grid, cell: number): void {
  const len = (g.obstEnd[cell] as number) - (g.obstStart[cell] as number);
  const room = Math.max(ROW_ROOM_MIN, 2 * len);
  // Pack first when the list holds more unused room than codes (then it stays within a few times
  // the codes it holds, and packing, O(cells + codes), comes at most once per that many codes added).
  if (g.obstTail + room > g.obstList.length && g.obstTail - g.obstLive > g.obstLive) pack(g);
  reserveList(g, room);
  const start = g.obstStart[cell] as number;
  g.obstList.copyWithin(g.obstTail, start, start + len);
  g.obstStart[cell] = g.obstTail;
  g.obstEnd[cell] = g.obstTail + len;
  g.obstCap[cell] = g.obstTail + room;
  g.obstTail += room;
}

/** Make room for `n` more codes at the end of the list. */
function reserveList(g: Grid, n: number): void {
  if (g.obstTail + n <= g.obstList.length) return;
  const list = new Int32Array(Math.max(2 * g.obstList.length, g.obstTail + n));
  list.set(g.obstList.subarray(0, g.obstTail));
  g.obstList = list;
}

/** Lay the rows out again in cell order, each without room to spare, dropping the rooms left behind. */
function pack(g: Grid): void {
  const nc = g.obstEnd.length;
  const list = new Int32Array(Math.max(16, 2 * g.obstLive));
  let tail = 0;
  for (let c = 0; c < nc; c++) {
    const start = g.obstStart[c] as number;
    const end = g.obstEnd[c] as number;
    list.set(g.obstList.subarray(start, end), tail);
    g.obstStart[c] = tail;
    tail += end - start;
    g.obstEnd[c] = tail;
    g.obstCap[c] = tail;
  }
  g.obstList = list;
  g.obstTail = tail;
}

/** Stop sharing the rows with a copy of the grid before editing them. */
function own(g: Grid): void {
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
