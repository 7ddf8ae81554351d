/**
 * Prediction: what each body runs into next. Each body holds its earliest predicted interaction
 * (collision or stop) and its next cell crossing; the heap key is the earlier of the two. Here are
 * the scans (which cells, levels and lines a body is tested against) and the next cell crossing;
 * one test and the choice of the earliest candidate are candidates.ts's, the contact times
 * pairTimes.ts's and contactTimes.ts's, functions of the motions alone; ties at one time are broken
 * in a canonical order (ids), so the prediction does not depend on the order bodies were added or
 * tested.
 */
import { EV_BODY, EV_NONE, EV_STOP } from "./bodyStore.js";
import { Candidates } from "./candidates.js";
import { axisExit } from "./cellExit.js";

const INF = Number.POSITIVE_INFINITY;
const side = new Float64Array(1);

export class Predictor extends Candidates {
  /** Recompute every body's predictions (after a rebuild or a change of obstacles or globals). */
  protected predictAll(): void {
    const b = this.store;
    for (let s = 0; s < b.slotCount; s++) if (b.ids[s] !== undefined) this.predict(s);
    this.dirty = false;
  }

  /** Recompute everything body s can run into next, and its next cell crossing. */
  protected predict(s: number): void {
    const b = this.store;
    // isMoving, inline (V8 did not inline the call here).
    const m = b.mot;
    const i = s << 3;
    const moving = m[i | 3] !== 0 || m[i | 4] !== 0 || m[i | 5] !== 0 || m[i | 6] !== 0;
    b.evTime[s] = INF;
    b.evKind[s] = EV_NONE;
    const tEnd = m[i | 7] as number;
    if (tEnd < INF) this.offer(s, Math.max(tEnd, this.now), EV_STOP, -1, 0);
    const grid = this.grid;
    // A boolean field compared by identity (a plain `!flat` is a full ToBoolean in V8's code).
    if (grid.flat !== true) {
      // Several levels hold bodies (grid.ts); the flat scans below are those of a plain grid, kept
      // inline: split into their own method, the gas ran 5-10 % slower (V8 inlined less).
      this.stamp++;
      this.scanAllLevels(s, moving);
      if (moving) for (const i of this.globalLines) this.testLine(s, i);
      this.heap.set(s, Math.min(b.evTime[s] as number, b.crossTime[s] as number));
      return;
    }
    // Cell coordinates in integers (cell / nx truncated is the row).
    const nx = grid.nx | 0;
    const ny = grid.ny | 0;
    const cell = grid.cellOf[s] as number;
    const cy = (cell / nx) | 0;
    const cx = cell - cy * nx;
    // The cells' obstacle lists are read only when one of the 3 x 3 lists something (grid.obstNear).
    const obstacles = moving && ((grid.obstNear[cell >> 5] as number) & (1 << (cell & 31))) !== 0;
    this.stamp++;
    for (let y = cy - 1; y <= cy + 1; y++) {
      if (y < 0 || y >= ny) continue;
      for (let x = cx - 1; x <= cx + 1; x++) {
        if (x < 0 || x >= nx) continue;
        this.scanCell(s, y * nx + x, moving);
        if (obstacles) this.scanCellObstacles(s, y * nx + x);
      }
    }
    if (moving) for (const i of this.globalLines) this.testLine(s, i);
    if (moving && (nx > 1 || ny > 1)) this.crossing(s, 0, cx, cy);
    else b.crossTime[s] = INF;
    const key = Math.min(b.evTime[s] as number, b.crossTime[s] as number);
    this.heap.set(s, key);
  }

  /** The scans of `predict` in a grid of several levels; sets the next crossing time. */
  private scanAllLevels(s: number, moving: boolean): void {
    const grid = this.grid;
    grid.locate(s);
    const k = grid.at[0] as number;
    const cx = grid.at[1] as number;
    const cy = grid.at[2] as number;
    const base = grid.base[k] as number;
    const nxk = grid.nxOf[k] as number;
    const nyk = grid.nyOf[k] as number;
    this.scanLevels(s, k, cx, cy, moving);
    if (moving)
      for (let y = Math.max(0, cy - 1); y <= Math.min(nyk - 1, cy + 1); y++)
        for (let x = Math.max(0, cx - 1); x <= Math.min(nxk - 1, cx + 1); x++)
          this.scanCellObstacles(s, base + y * nxk + x);
    if (moving && (nxk > 1 || nyk > 1)) this.crossing(s, k, cx, cy);
    else this.store.crossTime[s] = INF;
  }

  /** Test body s against the bodies in level j's cells [x0, x1] x [y0, y1] (clipped to the grid). */
  protected scanBlock(
    s: number,
    j: number,
    x0: number,
    x1: number,
    y0: number,
    y1: number,
    moving: boolean,
  ): void {
    const grid = this.grid;
    const nxj = grid.nxOf[j] as number;
    const base = grid.base[j] as number;
    const xa = Math.max(0, x0);
    const xb = Math.min(nxj - 1, x1);
    const ya = Math.max(0, y0);
    const yb = Math.min((grid.nyOf[j] as number) - 1, y1);
    for (let y = ya; y <= yb; y++)
      for (let x = xa; x <= xb; x++) this.scanCell(s, base + y * nxj + x, moving);
  }

  /**
   * Test body s against the bodies of a finer level j in its cells [x0, x1] x [y0, y1], or against
   * all that level's bodies when there are fewer of them than cells (a superset of candidates
   * changes no result: each pair's time depends on the two motions alone).
   */
  protected scanFiner(
    s: number,
    j: number,
    x0: number,
    x1: number,
    y0: number,
    y1: number,
    moving: boolean,
  ): void {
    const grid = this.grid;
    const cols = Math.max(0, Math.min((grid.nxOf[j] as number) - 1, x1) - Math.max(0, x0) + 1);
    const rows = Math.max(0, Math.min((grid.nyOf[j] as number) - 1, y1) - Math.max(0, y0) + 1);
    if (cols * rows <= (grid.count[j] as number)) {
      this.scanBlock(s, j, x0, x1, y0, y1, moving);
      return;
    }
    for (const o of grid.members[j] as number[]) {
      if (o === s || (!moving && this.opt.restingSkip && !this.isMoving(o))) continue;
      const t = this.pairTime(s, o);
      if (t !== INF) this.offer(s, t, EV_BODY, o, 0);
    }
  }

  /**
   * Test body s, of level k in level k's cell (cx, cy), against every body it is a candidate pair
   * with (grid.ts): of each coarser or equal level j, those in the 3x3 cells around its own cell
   * at level j; of each finer level, those in the cells under its 3x3 block at level k.
   */
  protected scanLevels(s: number, k: number, cx: number, cy: number, moving: boolean): void {
    for (const j of this.grid.occupied) {
      if (j >= k) {
        const X = cx >> (j - k);
        const Y = cy >> (j - k);
        this.scanBlock(s, j, X - 1, X + 1, Y - 1, Y + 1, moving);
      } else {
        const sh = k - j;
        this.scanFiner(
          s,
          j,
          (cx - 1) << sh,
          ((cx + 2) << sh) - 1,
          (cy - 1) << sh,
          ((cy + 2) << sh) - 1,
          moving,
        );
      }
    }
  }

  /**
   * Set crossTime[s] to the time at which body s (in level k's cell cx, cy) next leaves its cell,
   * and crossDir[s] to the direction. Stored, not returned: V8 boxes a double returned from a call
   * it does not inline (a heap allocation per crossing).
   */
  protected crossing(s: number, k: number, cx: number, cy: number): void {
    const b = this.store;
    const grid = this.grid;
    const m = b.mot;
    // Record offsets as s << 3 and fields as i | f (as in solvePair: no overflow checks).
    const i = s << 3;
    const t0 = m[i] as number;
    const lo = this.now - t0;
    const hax = 0.5 * (m[i | 5] as number);
    const hay = 0.5 * (m[i | 6] as number);
    let tx = INF;
    let ty = INF;
    let sx = 0;
    let sy = 0;
    if (hax === 0 && hay === 0) {
      // Uniform motion (the gas without friction or gravity): axisExit's division for the end
      // ahead on each axis, inline, with the same operands, so the same bits.
      const vx = m[i | 3] as number;
      const vy = m[i | 4] as number;
      if (vx > 0) {
        if (cx !== (grid.nxOf[k] as number) - 1) {
          sx = 1;
          tx = Math.max(lo, (grid.boundaryX((cx + 1) << k) - (m[i | 1] as number)) / vx);
        }
      } else if (vx < 0 && cx !== 0) {
        sx = -1;
        tx = Math.max(lo, (grid.boundaryX(cx << k) - (m[i | 1] as number)) / vx);
      }
      if (vy > 0) {
        if (cy !== (grid.nyOf[k] as number) - 1) {
          sy = 1;
          ty = Math.max(lo, (grid.boundaryY((cy + 1) << k) - (m[i | 2] as number)) / vy);
        }
      } else if (vy < 0 && cy !== 0) {
        sy = -1;
        ty = Math.max(lo, (grid.boundaryY(cy << k) - (m[i | 2] as number)) / vy);
      }
    } else {
      const hi = (m[i | 7] as number) - t0;
      // Cell bounds without allocation; edge cells extend to infinity. Level k's boundaries are
      // level 0's boundaries (cx << k), computed the same way.
      const x0 = cx === 0 ? -INF : grid.boundaryX(cx << k);
      const x1 = cx === (grid.nxOf[k] as number) - 1 ? INF : grid.boundaryX((cx + 1) << k);
      const y0 = cy === 0 ? -INF : grid.boundaryY(cy << k);
      const y1 = cy === (grid.nyOf[k] as number) - 1 ? INF : grid.boundaryY((cy + 1) << k);
      tx = axisExit(m[i | 1] as number, m[i | 3] as number, hax, lo, hi, x0, x1, side);
      sx = side[0] as number;
      ty = axisExit(m[i | 2] as number, m[i | 4] as number, hay, lo, hi, y0, y1, side);
      sy = side[0] as number;
    }
    // Directions: 0 -x, 1 +x, 2 -y, 3 +y.
    const best = Math.min(tx, ty);
    b.crossDir[s] = best === INF ? -1 : tx <= ty ? (sx < 0 ? 0 : 1) : sy < 0 ? 2 : 3;
    b.crossTime[s] = best === INF ? INF : Math.max(this.now, t0 + best);
  }
}
