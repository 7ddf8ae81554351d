/**
 * DiscGrid: a spatial hash of discs (id → x, y, r) for overlap queries while validating edits, so that
 * validating N added bodies costs about N, not N², and M lines or points placed among them about
 * M + N (smallestNearSegment). Cell size is fixed by the first disc (4 r); a query whose box spans
 * more cells than there are discs falls back to a scan of all discs.
 * The discs are kept in typed arrays by slot, each cell a chain of slots (about 120 bytes a disc; one
 * object per disc and an array per cell took 300 bytes, 300 MB for a scene of a million bodies).
 */
import { cellKey } from "../sim/cellKey.js";
import { placementPad, segmentXRange } from "../sim/segmentBand.js";
import { discsOverlap } from "./overlap.js";

/** The end of a cell's chain. */
const END = -1;
/** A segment query's cells, row by row: row, first and last column (reused). */
const rows: number[] = [];
const span = [0, 0];

export class DiscGrid {
  private readonly slotOf = new Map<string, number>();
  /** first slot of each cell's chain */
  private readonly heads = new Map<number | string, number>();
  /** per slot: the id (null when free), position, radius and the next slot of its cell */
  private ids: (string | null)[] = [];
  private xs = new Float64Array(16);
  private ys = new Float64Array(16);
  private rs = new Float64Array(16);
  private next = new Int32Array(16);
  private free: number[] = [];
  private cell = 0;
  private rMax = 0;

  get size(): number {
    return this.slotOf.size;
  }

  private keyAt(x: number, y: number): number | string {
    return cellKey(Math.floor(x / this.cell), Math.floor(y / this.cell));
  }

  /** A free slot (the arrays grow when full). */
  private take(): number {
    const reused = this.free.pop();
    if (reused !== undefined) return reused;
    const s = this.ids.length;
    if (s === this.xs.length) {
      const grow = <T extends Float64Array | Int32Array>(a: T, b: T): T => {
        b.set(a);
        return b;
      };
      const n = 2 * s;
      this.xs = grow(this.xs, new Float64Array(n));
      this.ys = grow(this.ys, new Float64Array(n));
      this.rs = grow(this.rs, new Float64Array(n));
      this.next = grow(this.next, new Int32Array(n));
    }
    this.ids.push(null);
    return s;
  }

  /** Puts disc `id` at (x, y) with radius r, in place of the disc of that id if there is one. */
  insert(id: string, x: number, y: number, r: number): void {
    this.remove(id);
    this.add(id, x, y, r);
  }

  /** insert for an id the grid does not hold (a new body: no lookup of an old one). */
  add(id: string, x: number, y: number, r: number): void {
    if (this.cell === 0) this.cell = 4 * r;
    if (r > this.rMax) this.rMax = r;
    const s = this.take();
    this.ids[s] = id;
    this.xs[s] = x;
    this.ys[s] = y;
    this.rs[s] = r;
    this.slotOf.set(id, s);
    const k = this.keyAt(x, y);
    this.next[s] = this.heads.get(k) ?? END;
    this.heads.set(k, s);
  }

  remove(id: string): void {
    const s = this.slotOf.get(id);
    if (s === undefined) return;
    this.slotOf.delete(id);
    const k = this.keyAt(this.xs[s] as number, this.ys[s] as number);
    const head = this.heads.get(k) as number;
    const after = this.next[s] as number;
    if (head === s) {
      if (after === END) this.heads.delete(k);
      else this.heads.set(k, after);
    } else {
      let p = head;
      while (this.next[p] !== s) p = this.next[p] as number;
      this.next[p] = after;
    }
    this.ids[s] = null;
    this.free.push(s);
  }

  clear(): void {
    this.slotOf.clear();
    this.heads.clear();
    this.ids = [];
    this.free = [];
  }

  /** The id of a disc (other than `except`) that the disc (x, y, r) overlaps, or null. Deterministic:
   *  the smallest such id. */
  findOverlap(x: number, y: number, r: number, except: string | null): string | null {
    const n = this.slotOf.size;
    if (n === 0) return null;
    const reach = r + this.rMax;
    const x0 = Math.floor((x - reach) / this.cell);
    const x1 = Math.floor((x + reach) / this.cell);
    const y0 = Math.floor((y - reach) / this.cell);
    const y1 = Math.floor((y + reach) / this.cell);
    // Far from the origin (cell numbers beyond 2^53) cx++ no longer moves and x0 === x1 even for a
    // wide box: scan every disc then, as for a box wider than the discs are many.
    const exact =
      Number.isSafeInteger(x0) &&
      Number.isSafeInteger(x1) &&
      Number.isSafeInteger(y0) &&
      Number.isSafeInteger(y1);
    let best: string | null = null;
    if (!exact || x1 - x0 + 1 > n || (x1 - x0 + 1) * (y1 - y0 + 1) > n) {
      for (let s = 0; s < this.ids.length; s++) best = this.smaller(s, x, y, r, except, best);
      return best;
    }
    for (let cx = x0; cx <= x1; cx++)
      for (let cy = y0; cy <= y1; cy++)
        for (let s = this.heads.get(cellKey(cx, cy)) ?? END; s !== END; s = this.next[s] as number)
          best = this.smaller(s, x, y, r, except, best);
    return best;
  }

  /**
   * The smallest id of the discs that can reach the segment (x1, y1)-(x2, y2) (a point when both
   * ends are equal) for which `hits(x, y, r)` holds: the cells within the largest radius (and the
   * segment's pad, and a cell more) of it, row by row, or every disc when they are fewer than those
   * cells (or the cell numbers exceed 2^53).
   */
  smallestNearSegment(
    x1: number,
    y1: number,
    x2: number,
    y2: number,
    hits: (x: number, y: number, r: number) => boolean,
  ): string | null {
    const n = this.slotOf.size;
    if (n === 0) return null;
    const c = this.cell;
    const reach = this.rMax + placementPad(x1, y1, x2, y2) + c;
    const r0 = Math.floor((Math.min(y1, y2) - reach) / c);
    const r1 = Math.floor((Math.max(y1, y2) + reach) / c);
    let cells = 0;
    let enumerable = Number.isSafeInteger(r0) && Number.isSafeInteger(r1) && r1 - r0 < n;
    rows.length = 0;
    for (let cy = r0; enumerable && cy <= r1; cy++) {
      if (!segmentXRange(x1, y1, x2, y2, cy * c - reach, (cy + 1) * c + reach, span)) continue;
      const c0 = Math.floor(((span[0] as number) - reach) / c);
      const c1 = Math.floor(((span[1] as number) + reach) / c);
      cells += c1 - c0 + 1;
      enumerable = Number.isSafeInteger(c0) && Number.isSafeInteger(c1) && cells <= n;
      rows.push(cy, c0, c1);
    }
    let best: string | null = null;
    const visit = (s: number): void => {
      const id = this.ids[s] as string | null;
      if (id === null || (best !== null && id >= best)) return;
      if (hits(this.xs[s] as number, this.ys[s] as number, this.rs[s] as number)) best = id;
    };
    if (!enumerable) {
      for (let s = 0; s < this.ids.length; s++) visit(s);
      return best;
    }
    for (let i = 0; i < rows.length; i += 3)
      for (let cx = rows[i + 1] as number; cx <= (rows[i + 2] as number); cx++)
        for (
          let s = this.heads.get(cellKey(cx, rows[i] as number)) ?? END;
          s !== END;
          s = this.next[s] as number
        )
          visit(s);
    return best;
  }

  /** The smaller of `best` and the id in slot s, if that disc (not free, not `except`) and (x, y, r)
   *  overlap. */
  private smaller(
    s: number,
    x: number,
    y: number,
    r: number,
    except: string | null,
    best: string | null,
  ): string | null {
    const id = this.ids[s] as string | null;
    if (id === null || id === except) return best;
    if (!discsOverlap(x, y, r, this.xs[s] as number, this.ys[s] as number, this.rs[s] as number)) return best;
    return best === null || id < best ? id : best;
  }
}
