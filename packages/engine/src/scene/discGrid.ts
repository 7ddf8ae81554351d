/**
 * DiscGrid: a spatial hash of discs (id → x, y, r) for overlap queries while validating edits, so that
 * validating N added bodies costs about N, not N². Cell size is fixed by the first disc (4 r); a query
 * whose box spans more cells than there are discs falls back to a scan of all discs.
 */
import { discsOverlap } from "./overlap.js";

interface Disc {
  id: string;
  x: number;
  y: number;
  r: number;
}

/** Cell numbers below this in size make a numeric key (cx + OFFSET) * SPAN + (cy + OFFSET), exact
 *  in a double (both factors < 2^26); beyond it the key is a string. */
const OFFSET = 2 ** 25;
const SPAN = 2 ** 26;

export class DiscGrid {
  private readonly discs = new Map<string, Disc>();
  private readonly cells = new Map<number | string, Disc[]>();
  private cell = 0;
  private rMax = 0;

  get size(): number {
    return this.discs.size;
  }

  private key(cx: number, cy: number): number | string {
    return cx > -OFFSET && cx < OFFSET && cy > -OFFSET && cy < OFFSET
      ? (cx + OFFSET) * SPAN + (cy + OFFSET)
      : `${cx}:${cy}`;
  }

  insert(id: string, x: number, y: number, r: number): void {
    this.remove(id);
    if (this.cell === 0) this.cell = 4 * r;
    if (r > this.rMax) this.rMax = r;
    const d: Disc = { id, x, y, r };
    this.discs.set(id, d);
    const k = this.key(Math.floor(x / this.cell), Math.floor(y / this.cell));
    const list = this.cells.get(k);
    if (list) list.push(d);
    else this.cells.set(k, [d]);
  }

  remove(id: string): void {
    const d = this.discs.get(id);
    if (!d) return;
    this.discs.delete(id);
    const k = this.key(Math.floor(d.x / this.cell), Math.floor(d.y / this.cell));
    const list = this.cells.get(k);
    if (!list) return;
    const i = list.indexOf(d);
    if (i >= 0) list.splice(i, 1);
    if (list.length === 0) this.cells.delete(k);
  }

  clear(): void {
    this.discs.clear();
    this.cells.clear();
  }

  /** The id of a disc (other than `except`) that the disc (x, y, r) overlaps, or null. Deterministic:
   *  the smallest such id. */
  findOverlap(x: number, y: number, r: number, except: string | null): string | null {
    if (this.discs.size === 0) return null;
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
    if (!exact || x1 - x0 + 1 > this.discs.size || (x1 - x0 + 1) * (y1 - y0 + 1) > this.discs.size)
      return smallestOverlap(this.discs.values(), x, y, r, except, null);
    let best: string | null = null;
    for (let cx = x0; cx <= x1; cx++)
      for (let cy = y0; cy <= y1; cy++) {
        const list = this.cells.get(this.key(cx, cy));
        if (list) best = smallestOverlap(list, x, y, r, except, best);
      }
    return best;
  }
}

/** The smallest of `best` and the ids of the discs in `list` (but `except`) that (x, y, r) overlaps. */
function smallestOverlap(
  list: Iterable<Disc>,
  x: number,
  y: number,
  r: number,
  except: string | null,
  best: string | null,
): string | null {
  for (const d of list)
    if (d.id !== except && discsOverlap(x, y, r, d.x, d.y, d.r) && (best === null || d.id < best))
      best = d.id;
  return best;
}
