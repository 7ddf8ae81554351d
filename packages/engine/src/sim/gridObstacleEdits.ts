/**
 * Edits of the grid's obstacle rows in place (gridObstacles.ts holds the rows): add or remove one
 * obstacle in the cells it covers at each built level, and renumber the codes after a removal from
 * the World's lists. The World's obstacle edits (obstacleUpkeep.ts) keep the grid's layout this way.
 *
 * The first edit gives the packed rows ends and rooms of their own (editInPlace). A row that
 * outgrows its room moves to the end of the list with twice the room (the list grows by doubling,
 * and is packed again when the rooms left behind outnumber the codes), so adding or removing one
 * obstacle costs the cells it covers at each built level, not the grid. Every edit keeps obstBits
 * and obstNear exact.
 */
import {
  editInPlace,
  forEachAround,
  type GridObstacles,
  hasRow,
  markNear,
  own,
  reserveList,
} from "./gridObstacles.js";

/** Fewest codes of room a row gets when it first grows. */
const ROW_ROOM_MIN = 4;

/** Register obstacle `code` in the level-0 cells `cells` (distinct) and their cells at every built level. */
export function addObstacle(g: GridObstacles, code: number, cells: readonly number[]): void {
  editInPlace(g);
  forEachCell(g, cells, (cell) => insert(g, cell, code));
}

/** Take obstacle `code`, registered in the level-0 cells `cells` (as addObstacle or setObstacles put it), out of every row. */
export function removeObstacle(g: GridObstacles, code: number, cells: readonly number[]): void {
  editInPlace(g);
  forEachCell(g, cells, (cell) => remove(g, cell, code));
}

/**
 * The World's list dropped line `line` (or, with `line` undefined, point `point`) and closed the
 * gap: renumber the codes after it, one pass over the list of codes (the rows stay where they are).
 */
export function renumberAfterRemoval(g: GridObstacles, line: number | undefined, point = 0): void {
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
function forEachCell(g: GridObstacles, cells: readonly number[], visit: (cell: number) => void): void {
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

function insert(g: GridObstacles, cell: number, code: number): void {
  if (g.obstEnd[cell] === g.obstCap[cell]) moveRow(g, cell);
  const end = g.obstEnd[cell] as number;
  g.obstList[end] = code;
  g.obstEnd[cell] = end + 1;
  g.obstBits[cell >> 5] = (g.obstBits[cell >> 5] as number) | (1 << (cell & 31));
  if (end === (g.obstStart[cell] as number) && cell < g.nx * g.ny) markNear(g, cell);
  g.obstLive++;
}

function remove(g: GridObstacles, cell: number, code: number): void {
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

/** Level-0 cell c's row became empty: each cell of its 3 x 3 is near obstacles only if a cell of its own 3 x 3 has a row. */
function unmarkNear(g: GridObstacles, c: number): void {
  forEachAround(g, c, (n) => {
    let near = false;
    forEachAround(g, n, (m) => {
      near ||= hasRow(g, m);
    });
    if (!near) g.obstNear[n >> 5] = (g.obstNear[n >> 5] as number) & ~(1 << (n & 31));
  });
}

/** Move cell's full row to the end of the list with twice its room. */
function moveRow(g: GridObstacles, cell: number): void {
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

/** Lay the rows out again in cell order, each without room to spare, dropping the rooms left behind. */
function pack(g: GridObstacles): void {
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
