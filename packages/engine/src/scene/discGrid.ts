/**
 * DiscGrid: a spatial hash of discs (id → x, y, r) for overlap queries while validating edits, so that
 * validating N added bodies costs about N, not N². Cell size is fixed by the first disc (4 r); a query
 * whose box spans more cells than there are discs falls back to a scan of all discs.
 */
import { discsOverlap } from "./overlap.js";

interface Disc {
  x: number;
  y: number;
  r: number;
}

export class DiscGrid {
  private readonly discs = new Map<string, Disc>();
  private readonly cells = new Map<string, string[]>();
  private cell = 0;
  private rMax = 0;

  get size(): number {
    return this.discs.size;
  }

  private key(cx: number, cy: number): string {
    return `${cx}:${cy}`;
  }

  insert(id: string, x: number, y: number, r: number): void {
    this.remove(id);
    if (this.cell === 0) this.cell = 4 * r;
    if (r > this.rMax) this.rMax = r;
    this.discs.set(id, { x, y, r });
    const k = this.key(Math.floor(x / this.cell), Math.floor(y / this.cell));
    const list = this.cells.get(k);
    if (list) list.push(id);
    else this.cells.set(k, [id]);
  }

  remove(id: string): void {
    const d = this.discs.get(id);
    if (!d) return;
    this.discs.delete(id);
    const k = this.key(Math.floor(d.x / this.cell), Math.floor(d.y / this.cell));
    const list = this.cells.get(k);
    if (!list) return;
    const i = list.indexOf(id);
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
    let best: string | null = null;
    const test = (id: string, d: Disc) => {
      if (id !== except && discsOverlap(x, y, r, d.x, d.y, d.r) && (best === null || id < best)) best = id;
    };
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
    if (!exact || x1 - x0 + 1 > this.discs.size || (x1 - x0 + 1) * (y1 - y0 + 1) > this.discs.size) {
      for (const [id, d] of this.discs) test(id, d);
      return best;
    }
    for (let cx = x0; cx <= x1; cx++)
      for (let cy = y0; cy <= y1; cy++) {
        const list = this.cells.get(this.key(cx, cy));
        if (list) for (const id of list) test(id, this.discs.get(id) as Disc);
      }
    return best;
  }
}
