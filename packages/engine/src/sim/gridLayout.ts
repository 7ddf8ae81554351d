/**
 * The broad-phase grid's geometry (grid.ts): its nested levels of cells, and where a point or a
 * body is in them. No bodies and no obstacles here: GridObstacles (gridObstacles.ts) and Grid
 * (grid.ts) extend this class, so a grid is one object whose fields the hot path reads directly.
 *
 * Levels (for scenes of very different radii): level k has cells of side w * 2^k over the same
 * origin, so level k's column of a point is its level-0 column >> k and every level-k boundary is
 * also a level-0 boundary. Each body is registered in one level, the finest whose cells fit it
 * (`levelFor`). The top level may be a single cell, which takes any radius; the levels always go
 * up to it.
 *
 * The outermost rows and columns of every level extend to infinity, so a body leaving the region
 * stays in an edge cell and causes no more crossing events (a disc flying away for ever costs
 * nothing). Cell indices are global: level k's cells are base[k] ... base[k] + nxOf[k] * nyOf[k] - 1,
 * row by row.
 */

import { mulPow2 } from "../roots/pow2.js";
import { GRID_CELL_MARGIN } from "../tolerances.js";

const INF = Number.POSITIVE_INFINITY;

/** Most levels a grid has: cells 2^(GRID_LEVELS_MAX - 1) times the finest ones reach any region. */
const GRID_LEVELS_MAX = 31;

export class GridLayout {
  ox = 0;
  oy = 0;
  /** Cell side at level 0. */
  w = 1;
  /** Columns and rows at level 0. */
  nx = 1;
  ny = 1;
  /** Number of levels (>= 1). */
  levels = 1;
  /** Per level: columns, rows, first global cell index (and the total at index `levels`), largest radius it fits. */
  nxOf: Int32Array = new Int32Array([1]);
  nyOf: Int32Array = new Int32Array([1]);
  base: Int32Array = new Int32Array([0, 1]);
  fitR: Float64Array = new Float64Array([INF]);

  /**
   * Lay the levels out: level-0 cells of side w, nx * ny of them, lower-left corner (ox, oy), and
   * coarser levels up to one of a single cell, which fits any radius (so a disc of any size has a
   * level without a rebuild). Level 0 fits `sizedFor`, the radius w was computed from (w is at
   * least 2 * GRID_CELL_MARGIN times it, up to rounding). nx = ny = 1 gives one cell for everything.
   */
  protected layOut(ox: number, oy: number, w: number, nx: number, ny: number, sizedFor: number): void {
    this.ox = ox;
    this.oy = oy;
    this.w = w;
    // Whole numbers below 2^31 (cell counts): stored as small integers, so that the hot path's cell
    // arithmetic runs in integers (a field that once held a double stays a boxed double).
    this.nx = nx | 0;
    this.ny = ny | 0;
    const nxOf: number[] = [];
    const nyOf: number[] = [];
    const fit: number[] = [];
    for (let k = 0; k < GRID_LEVELS_MAX; k++) {
      const cx = ((nx - 1) >> k) + 1;
      const cy = ((ny - 1) >> k) + 1;
      const single = cx === 1 && cy === 1;
      nxOf.push(cx);
      nyOf.push(cy);
      // Level 0 fits the radius its side was computed from, whatever the rounding of w / (2 margin).
      fit.push(single ? INF : Math.max(mulPow2(w, k) / (2 * GRID_CELL_MARGIN), k === 0 ? sizedFor : 0));
      if (single) break;
    }
    const levels = nxOf.length;
    this.levels = levels;
    this.nxOf = Int32Array.from(nxOf);
    this.nyOf = Int32Array.from(nyOf);
    this.fitR = Float64Array.from(fit);
    this.base = new Int32Array(levels + 1);
    for (let k = 0; k < levels; k++)
      this.base[k + 1] = (this.base[k] as number) + (nxOf[k] as number) * (nyOf[k] as number);
  }

  /** Give `g` this layout (the arrays are never written after layOut, so they are shared). */
  protected copyLayoutInto(g: GridLayout): void {
    g.ox = this.ox;
    g.oy = this.oy;
    g.w = this.w;
    g.nx = this.nx;
    g.ny = this.ny;
    g.levels = this.levels;
    g.nxOf = this.nxOf;
    g.nyOf = this.nyOf;
    g.base = this.base;
    g.fitR = this.fitR;
  }

  /** Finest level whose cells fit a disc of radius r (the top level, a single cell, fits any). */
  levelFor(r: number): number {
    let k = 0;
    while (k < this.levels - 1 && r > (this.fitR[k] as number)) k++;
    return k;
  }

  /** Global index of the level-k cell holding the level-0 cell (cx, cy). */
  cellAt(k: number, cx: number, cy: number): number {
    return (this.base[k] as number) + (cy >> k) * (this.nxOf[k] as number) + (cx >> k);
  }

  /** Column of x (clamped to the grid: edge columns extend to infinity). */
  column(x: number): number {
    const c = Math.floor((x - this.ox) / this.w);
    return c < 0 ? 0 : c >= this.nx ? this.nx - 1 : c;
  }

  row(y: number): number {
    const c = Math.floor((y - this.oy) / this.w);
    return c < 0 ? 0 : c >= this.ny ? this.ny - 1 : c;
  }

  /** x of the boundary between column c - 1 and column c. */
  boundaryX(c: number): number {
    return this.ox + c * this.w;
  }

  boundaryY(r: number): number {
    return this.oy + r * this.w;
  }

  /** Cell rectangle [x0, x1] x [y0, y1]; edge cells extend to infinity. */
  cellRect(cx: number, cy: number): [number, number, number, number] {
    const inf = Number.POSITIVE_INFINITY;
    return [
      cx === 0 ? -inf : this.boundaryX(cx),
      cx === this.nx - 1 ? inf : this.boundaryX(cx + 1),
      cy === 0 ? -inf : this.boundaryY(cy),
      cy === this.ny - 1 ? inf : this.boundaryY(cy + 1),
    ];
  }
}
