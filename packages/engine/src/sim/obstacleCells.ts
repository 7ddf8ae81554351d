/**
 * ObstacleCells: the lines or points a disc is checked against when it is placed (a World edit, a
 * scene's action), found near the disc instead of scanned, so that n discs placed among m obstacles
 * cost about n + m tests, not n × m. Each obstacle is kept by id with a payload (what the caller's
 * overlap test reads); `smallestHit` gives the smallest id of those the test holds for, the answer
 * a scan of all of them gives (every refusal names the smallest id hit).
 *
 * Segments and points are hashed in square cells of side 2^k, at several levels k (cellKey.ts):
 * - at its own level, the finest whose cells are at least 1/CAP of its extent, each is registered
 *   in the cells it passes (about 2 CAP at most: a long wall costs no more than a short one);
 * - in the fine table of each query size met so far (level q: cells at least the disc's box), each
 *   whose own level is not coarser is registered too.
 * A disc's box (radius plus pad) spans at most 2 × 2 cells of its fine table and of every coarser
 * own level, so a query reads a few cells per level. Every box is widened by placementPad, so a pair
 * the caller's test (in doubles) finds overlapping always shares a cell. Infinite lines and rays have
 * no extent: every query tests all of them (a scan; they are few). The first queries, and all
 * while the obstacles are few, scan everything: placing one disc does not pay for the tables.
 */
import { exponentOf, mulPow2 } from "../roots/pow2.js";
import { cellKey } from "./cellKey.js";
import { placementPad, segmentXRange } from "./segmentBand.js";

/** A segment's own level has cells at least 1/CAP of its extent (it passes at most about 2 CAP). */
const CAP = 8;
/** Most cells an obstacle is registered in at a level (a bound its extent keeps; beyond: `wide`). */
const CELLS_MAX = (CAP + 3) * (CAP + 3);
/** A query reuses a fine table up to this many levels coarser than its size instead of building one. */
const FINE_REUSE = 2;
/** Queries answered by a scan before the tables are built, and the fewest obstacles they pay for. */
const SCAN_QUERIES = 8;
const SCAN_SIZE = 32;
/** Cell sides stay normal doubles. */
const MIN_LEVEL = -1022;
const MAX_LEVEL = 1023;

/** The cells of one level: slots by cell key, and the slots whose cells could not be enumerated. */
interface Table {
  readonly level: number;
  readonly side: number;
  readonly cells: Map<number | string, number[]>;
  readonly wide: Set<number>;
  count: number;
}

export interface ObstacleCellsOptions {
  /** Queries answered by a scan before the tables are built (0: a caller that scanned already, tests). */
  scanQueries?: number;
  /** Fewest obstacles for which the tables are built (tests pass 0 to index a few). */
  scanSize?: number;
}

/** Smallest k with 2^k >= v (v > 0), within [MIN_LEVEL, MAX_LEVEL] (from the bits: pow2.ts). */
export function levelAtLeast(v: number): number {
  if (!(v > mulPow2(1, MIN_LEVEL))) return MIN_LEVEL;
  if (!(v <= mulPow2(1, MAX_LEVEL))) return MAX_LEVEL;
  const e = exponentOf(v);
  return v === mulPow2(1, e) ? e : e + 1;
}

export class ObstacleCells<T> {
  private readonly slotOf = new Map<string, number>();
  /** Per slot: id (null when free), payload, x1 y1 x2 y2 pad (5 numbers), own level (NaN: infinite). */
  private ids: (string | null)[] = [];
  private items: (T | undefined)[] = [];
  private geo: number[] = [];
  private own: number[] = [];
  private free: number[] = [];
  private readonly unbounded = new Set<number>();
  private readonly fine = new Map<number, Table>();
  private fineLevels: number[] = [];
  private readonly owned = new Map<number, Table>();
  private ownLevels: number[] = [];
  private indexed = false;
  private queries = 0;
  private seen = new Int32Array(16);
  private stamp = 0;
  private readonly scanQueries: number;
  private readonly scanSize: number;
  private readonly keys: (number | string)[] = [];
  private readonly span: number[] = [0, 0];

  constructor(options: ObstacleCellsOptions = {}) {
    this.scanQueries = options.scanQueries ?? SCAN_QUERIES;
    this.scanSize = options.scanSize ?? SCAN_SIZE;
  }

  get size(): number {
    return this.slotOf.size;
  }

  /**
   * Put obstacle `id` (in place of the one of that id, if any): the segment (x1, y1)-(x2, y2), a
   * point when both ends are equal, or, `bounded` false, an infinite line or ray (tested by every query).
   */
  set(id: string, item: T, x1: number, y1: number, x2: number, y2: number, bounded: boolean): void {
    this.delete(id);
    const s = this.free.pop() ?? this.ids.length;
    if (s === this.ids.length) {
      this.ids.push(null);
      this.items.push(undefined);
      this.own.push(0);
      this.geo.push(0, 0, 0, 0, 0);
    }
    this.ids[s] = id;
    this.items[s] = item;
    this.slotOf.set(id, s);
    const pad = placementPad(x1, y1, x2, y2);
    const g = this.geo;
    g[5 * s] = x1;
    g[5 * s + 1] = y1;
    g[5 * s + 2] = x2;
    g[5 * s + 3] = y2;
    g[5 * s + 4] = pad;
    if (!bounded) {
      this.own[s] = Number.NaN;
      this.unbounded.add(s);
      return;
    }
    this.own[s] = levelAtLeast((Math.max(Math.abs(x2 - x1), Math.abs(y2 - y1)) + 2 * pad) / CAP);
    if (this.indexed) this.register(s);
  }

  delete(id: string): void {
    const s = this.slotOf.get(id);
    if (s === undefined) return;
    if (!this.unbounded.delete(s) && this.indexed) {
      const own = this.own[s] as number;
      const table = this.owned.get(own) as Table;
      this.removeFrom(table, s);
      if (table.count === 0) {
        this.owned.delete(own);
        this.ownLevels = this.ownLevels.filter((k) => k !== own);
      }
      for (const L of this.fineLevels) if (L >= own) this.removeFrom(this.fine.get(L) as Table, s);
    }
    this.slotOf.delete(id);
    this.ids[s] = null;
    this.items[s] = undefined;
    this.free.push(s);
  }

  /**
   * The smallest id of the obstacles for which `hits` holds, among those near the disc (x, y, r)
   * and every infinite one: the smallest id of all for which it holds, whenever `hits` holds only
   * for obstacles that the disc (in doubles) overlaps.
   */
  smallestHit(x: number, y: number, r: number, hits: (item: T) => boolean): string | undefined {
    this.queries++;
    if (!this.indexed) {
      if (this.queries <= this.scanQueries || this.slotOf.size < this.scanSize) return this.scan(hits);
      this.indexed = true;
      for (let s = 0; s < this.ids.length; s++)
        if (this.ids[s] !== null && !this.unbounded.has(s)) this.register(s);
    }
    if (this.seen.length < this.ids.length) this.seen = new Int32Array(2 * this.ids.length);
    if (this.stamp === 0x3fffffff) {
      this.seen.fill(0);
      this.stamp = 0;
    }
    const stamp = ++this.stamp;
    let best: string | undefined;
    const consider = (s: number): void => {
      if (this.seen[s] === stamp) return;
      this.seen[s] = stamp;
      const id = this.ids[s] as string;
      if ((best === undefined || id < best) && hits(this.items[s] as T)) best = id;
    };
    for (const s of this.unbounded) consider(s);
    const half = r + placementPad(x, y, r, 0);
    const table = this.fineTable(levelAtLeast(2 * half));
    if (!this.visitBox(table, x, y, half, consider)) return this.scan(hits);
    for (let i = this.ownLevels.length - 1; i >= 0; i--) {
      const k = this.ownLevels[i] as number;
      if (k <= table.level) break;
      if (!this.visitBox(this.owned.get(k) as Table, x, y, half, consider)) return this.scan(hits);
    }
    return best;
  }

  /** The smallest id of all obstacles for which `hits` holds. */
  private scan(hits: (item: T) => boolean): string | undefined {
    let best: string | undefined;
    for (let s = 0; s < this.ids.length; s++) {
      const id = this.ids[s] as string | null;
      if (id !== null && (best === undefined || id < best) && hits(this.items[s] as T)) best = id;
    }
    return best;
  }

  /** Visit the slots in the cells of the box (x ± half, y ± half) of `table`; false when they cannot
   *  be enumerated (cell numbers beyond 2^53, or more cells than a query's box can span). */
  private visitBox(table: Table, x: number, y: number, half: number, visit: (s: number) => void): boolean {
    const side = table.side;
    const x0 = Math.floor((x - half) / side);
    const x1 = Math.floor((x + half) / side);
    const y0 = Math.floor((y - half) / side);
    const y1 = Math.floor((y + half) / side);
    if (!safeRange(x0, x1) || !safeRange(y0, y1)) return false;
    for (let cx = x0; cx <= x1; cx++)
      for (let cy = y0; cy <= y1; cy++) {
        const list = table.cells.get(cellKey(cx, cy));
        if (list !== undefined) for (const s of list) visit(s);
      }
    for (const s of table.wide) visit(s);
    return true;
  }

  /** The fine table for queries of level q: one up to FINE_REUSE levels coarser, or a new one. */
  private fineTable(q: number): Table {
    for (const L of this.fineLevels) if (L >= q && L <= q + FINE_REUSE) return this.fine.get(L) as Table;
    const table = newTable(q);
    for (let s = 0; s < this.ids.length; s++)
      if (this.ids[s] !== null && (this.own[s] as number) <= q) this.addTo(table, s);
    this.fine.set(q, table);
    this.fineLevels = [...this.fineLevels, q].sort((a, b) => a - b);
    return table;
  }

  /** Register slot s at its own level and in the fine tables not finer than it. */
  private register(s: number): void {
    const own = this.own[s] as number;
    let table = this.owned.get(own);
    if (table === undefined) {
      table = newTable(own);
      this.owned.set(own, table);
      this.ownLevels = [...this.ownLevels, own].sort((a, b) => a - b);
    }
    this.addTo(table, s);
    for (const L of this.fineLevels) if (L >= own) this.addTo(this.fine.get(L) as Table, s);
  }

  private addTo(table: Table, s: number): void {
    table.count++;
    if (!this.cellsOf(s, table.side)) {
      table.wide.add(s);
      return;
    }
    for (const key of this.keys) {
      const list = table.cells.get(key);
      if (list === undefined) table.cells.set(key, [s]);
      else list.push(s);
    }
  }

  private removeFrom(table: Table, s: number): void {
    table.count--;
    if (table.wide.delete(s)) return;
    this.cellsOf(s, table.side); // the same keys addTo registered s under
    for (const key of this.keys) {
      const list = table.cells.get(key) as number[];
      const at = list.indexOf(s);
      list[at] = list[list.length - 1] as number;
      list.pop();
      if (list.length === 0) table.cells.delete(key);
    }
  }

  /**
   * Set `keys` to the cells of side `side` that slot s's segment, widened by its pad, passes (row
   * by row, segmentBand.ts); false when they cannot be enumerated (cell numbers beyond 2^53).
   */
  private cellsOf(s: number, side: number): boolean {
    const g = this.geo;
    const x1 = g[5 * s] as number;
    const y1 = g[5 * s + 1] as number;
    const x2 = g[5 * s + 2] as number;
    const y2 = g[5 * s + 3] as number;
    const pad = g[5 * s + 4] as number;
    const keys = this.keys;
    keys.length = 0;
    const r0 = Math.floor((Math.min(y1, y2) - pad) / side);
    const r1 = Math.floor((Math.max(y1, y2) + pad) / side);
    if (!safeRange(r0, r1)) return false;
    const span = this.span;
    for (let cy = r0; cy <= r1; cy++) {
      if (!segmentXRange(x1, y1, x2, y2, cy * side - pad, (cy + 1) * side + pad, span)) continue;
      const c0 = Math.floor(((span[0] as number) - pad) / side);
      const c1 = Math.floor(((span[1] as number) + pad) / side);
      if (!safeRange(c0, c1) || keys.length + c1 - c0 + 1 > CELLS_MAX) return false;
      for (let cx = c0; cx <= c1; cx++) keys.push(cellKey(cx, cy));
    }
    return true;
  }
}

function newTable(level: number): Table {
  return { level, side: mulPow2(1, level), cells: new Map(), wide: new Set(), count: 0 };
}

/** Whether a..b is a range of whole numbers a loop can step through (and not an absurd one). */
function safeRange(a: number, b: number): boolean {
  return Number.isSafeInteger(a) && Number.isSafeInteger(b) && b - a <= CELLS_MAX;
}
