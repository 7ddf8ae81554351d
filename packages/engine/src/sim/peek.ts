/**
 * Undo log for looking ahead at the next event in place (World.nextEventTime).
 *
 * Finding the next collision or stop may first need internal queue items processed: cell
 * crossings (which move a body's grid registration and change its crossing and, through new
 * partners, its prediction) and stale predictions (recomputed). Each only touches the popped slot
 * and the grid, so the look-ahead saves a slot's prediction fields and queue key before it first
 * touches it, and each grid move with the slot's neighbours in the cell it leaves. `undo` then puts
 * everything back exactly: grid moves in reverse order (each slot relinked between the same
 * neighbours, so every cell's list order is restored too), then every saved slot's fields and key.
 * The world is then bit for bit as before, except for caches that never change a result (the queue's
 * bucket layout, the prediction stamp and the pair memo). Cost: O(1) per item processed.
 */
import type { BodyStore } from "./bodyStore.js";
import type { CalendarQueue } from "./calendarQueue.js";
import type { Grid } from "./grid.js";

/** Float fields saved per slot: queue key, evTime, evOtherVersion, crossTime. */
const NF = 4;
/** Integer fields saved per slot: slot, evKind, evOther, evAux, crossDir. */
const NI = 5;

export class PeekLog {
  /** Per slot: the look-ahead that last saved it (a slot is saved once per look-ahead). */
  private mark: Int32Array = new Int32Array(0);
  private epoch = 0;
  private saved = 0;
  private f: Float64Array = new Float64Array(NF * 16);
  private i: Int32Array = new Int32Array(NI * 16);
  /** Grid moves: slot, cell left, previous and next slot in that cell's list. */
  private moves: Int32Array = new Int32Array(4 * 16);
  private nMoves = 0;

  /** Start a look-ahead over slots 0 .. capacity - 1 (the log must be empty). */
  begin(capacity: number): void {
    // Sized to the store (which a trim may shrink): a fresh array holds no mark of this epoch (>= 1).
    if (this.mark.length !== capacity) this.mark = new Int32Array(capacity);
    this.epoch++;
    if (this.epoch === 0x7fffffff) {
      this.mark.fill(0);
      this.epoch = 1;
    }
  }

  /** Save slot s's prediction fields and its queue key (call before the look-ahead first changes them). */
  save(b: BodyStore, s: number, key: number): void {
    if (this.mark[s] === this.epoch) return;
    this.mark[s] = this.epoch;
    const k = this.saved++;
    if (NI * this.saved > this.i.length) {
      this.f = growF(this.f);
      this.i = growI(this.i);
    }
    const f = this.f;
    const i = this.i;
    f[NF * k] = key;
    f[NF * k + 1] = b.evTime[s] as number;
    f[NF * k + 2] = b.evOtherVersion[s] as number;
    f[NF * k + 3] = b.crossTime[s] as number;
    i[NI * k] = s;
    i[NI * k + 1] = b.evKind[s] as number;
    i[NI * k + 2] = b.evOther[s] as number;
    i[NI * k + 3] = b.evAux[s] as number;
    i[NI * k + 4] = b.crossDir[s] as number;
  }

  /** Record where slot s is registered (call just before the grid moves it). */
  recordMove(g: Grid, s: number): void {
    if (4 * (this.nMoves + 1) > this.moves.length) this.moves = growI(this.moves);
    const m = this.moves;
    const k = 4 * this.nMoves++;
    m[k] = s;
    m[k + 1] = g.cellOf[s] as number;
    m[k + 2] = g.prev[s] as number;
    m[k + 3] = g.next[s] as number;
  }

  /** Put the grid, the saved fields and the queue keys back as they were at `begin`; empties the log. */
  undo(b: BodyStore, g: Grid, q: CalendarQueue): void {
    const m = this.moves;
    for (let k = 4 * (this.nMoves - 1); k >= 0; k -= 4) {
      const s = m[k] as number;
      const cell = m[k + 1] as number;
      const p = m[k + 2] as number;
      const n = m[k + 3] as number;
      g.remove(s);
      // Every later move is undone, so p and n are neighbours again in `cell`: relink s between them.
      g.cellOf[s] = cell;
      g.prev[s] = p;
      g.next[s] = n;
      if (p >= 0) g.next[p] = s;
      else g.head[cell] = s;
      if (n >= 0) g.prev[n] = s;
    }
    this.nMoves = 0;
    const f = this.f;
    const i = this.i;
    for (let k = 0; k < this.saved; k++) {
      const s = i[NI * k] as number;
      b.evTime[s] = f[NF * k + 1] as number;
      b.evOtherVersion[s] = f[NF * k + 2] as number;
      b.crossTime[s] = f[NF * k + 3] as number;
      b.evKind[s] = i[NI * k + 1] as number;
      b.evOther[s] = i[NI * k + 2] as number;
      b.evAux[s] = i[NI * k + 3] as number;
      b.crossDir[s] = i[NI * k + 4] as number;
      q.set(s, f[NF * k] as number);
    }
    this.saved = 0;
  }
}

function growF(a: Float64Array): Float64Array {
  const c = new Float64Array(2 * a.length);
  c.set(a);
  return c;
}

function growI(a: Int32Array): Int32Array {
  const c = new Int32Array(2 * a.length);
  c.set(a);
  return c;
}
