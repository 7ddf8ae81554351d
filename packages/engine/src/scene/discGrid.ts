/**
 * DiscGrid: a spatial hash of discs (id → x, y, r) for overlap queries while validating edits, so that
 * validating N added bodies costs about N, not N². Cell size is fixed by the first disc (4 r); a query
 * whose box spans more cells than there are discs falls back to a scan of all discs.
 * The discs are kept in typed arrays by slot, each cell a chain of slots (about 120 bytes a disc; one
 * object per disc and an array per cell took 300 bytes, 300 MB for a scene of a million bodies).
 */
import { discsOverlap } from "./overlap.js";

/** Cell numbers below this in size make a small integer key, -1 - ((cx + SMALL) * 2 SMALL + (cy +
 *  SMALL)), in [-2^30, -1] (a small integer for V8, whatever the build); below OFFSET a numeric key
 *  (cx + OFFSET) * SPAN + (cy + OFFSET), exact in a double (both factors < 2^26) and > 0; beyond it
 *  the key is a string. The three kinds never meet. */
const SMALL = 2 ** 14;
const OFFSET = 2 ** 25;
const SPAN = 2 ** 26;
/** The end of a cell's chain. */
const END = -1;

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

  private key(cx: number, cy: number): number | string {
    if (cx > -SMALL && cx < SMALL && cy > -SMALL && cy < SMALL)
      return -1 - ((cx + SMALL) * 2 * SMALL + (cy + SMALL));
    return cx > -OFFSET && cx < OFFSET && cy > -OFFSET && cy < OFFSET
      ? (cx + OFFSET) * SPAN + (cy + OFFSET)
      : `${cx}:${cy}`;
  }

  private keyAt(x: number, y: number): number | string {
    return this.key(Math.floor(x / this.cell), Math.floor(y / this.cell));
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
        for (let s = this.heads.get(this.key(cx, cy)) ?? END; s !== END; s = this.next[s] as number)
          best = this.smaller(s, x, y, r, except, best);
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
