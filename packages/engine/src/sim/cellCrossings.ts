/**
 * Cell crossings: moving a body to the next cell of its level when its centre crosses a boundary,
 * and testing it against the bodies that have just become its neighbours, at every level of the
 * grid (grid.ts). A crossing never changes a motion; it only adds candidate pairs.
 */
import { Predictor } from "./predictor.js";

export class CellCrossings extends Predictor {
  protected processCrossing(s: number): void {
    if (this.grid.flat !== true) {
      this.crossLevels(s);
      return;
    }
    // Only level 0 holds bodies: a plain grid's crossing, inline (as in predict).
    const b = this.store;
    const grid = this.grid;
    const nx = grid.nx | 0;
    const cell = grid.cellOf[s] as number;
    // In integers: cell / nx truncated is the row (cell >= 0).
    let cy = (cell / nx) | 0;
    let cx = cell - cy * nx;
    const dir = b.crossDir[s] as number;
    if (dir === 0) cx--;
    else if (dir === 1) cx++;
    else if (dir === 2) cy--;
    else cy++;
    const to = cy * nx + cx;
    grid.move(s, to);
    // The strip lies in the new cell's 3 x 3: its obstacle lists are read only when one of those
    // lists something (grid.obstNear).
    const obstacles = ((grid.obstNear[to >> 5] as number) & (1 << (to & 31))) !== 0;
    this.stamp++;
    // The strip (one column or one row of three cells), clipped to the grid, scanned by one loop:
    // one call site, so that V8 inlines the scans (and the pair test) once, in full.
    const xa = Math.max(0, dir === 1 ? cx + 1 : cx - 1);
    const xb = Math.min(nx - 1, dir === 0 ? cx - 1 : cx + 1);
    const ya = Math.max(0, dir === 3 ? cy + 1 : cy - 1);
    const yb = Math.min(grid.ny - 1, dir === 2 ? cy - 1 : cy + 1);
    for (let y = ya; y <= yb; y++)
      for (let x = xa; x <= xb; x++) {
        const c = y * nx + x;
        this.scanCell(s, c, true);
        if (obstacles) this.scanCellObstacles(s, c);
      }
    this.crossing(s, 0, cx, cy);
    this.heap.set(s, Math.min(b.evTime[s] as number, b.crossTime[s] as number));
  }

  /** A crossing in a grid of several levels. */
  private crossLevels(s: number): void {
    const b = this.store;
    const grid = this.grid;
    grid.locate(s);
    const k = grid.at[0] as number;
    const ocx = grid.at[1] as number;
    const ocy = grid.at[2] as number;
    const base = grid.base[k] as number;
    const nxk = grid.nxOf[k] as number;
    const nyk = grid.nyOf[k] as number;
    const dir = b.crossDir[s] as number;
    const cx = dir === 0 ? ocx - 1 : dir === 1 ? ocx + 1 : ocx;
    const cy = dir === 2 ? ocy - 1 : dir === 3 ? ocy + 1 : ocy;
    grid.move(s, base + cy * nxk + cx);
    // Only the row or column that just became adjacent holds new partners.
    this.stamp++;
    const sx = dir === 0 ? cx - 1 : dir === 1 ? cx + 1 : cx;
    const sy = dir === 2 ? cy - 1 : dir === 3 ? cy + 1 : cy;
    // The new strip at level k: (x0, y0)-(x1, y1).
    const x0 = dir <= 1 ? sx : cx - 1;
    const x1 = dir <= 1 ? sx : cx + 1;
    const y0 = dir <= 1 ? cy - 1 : sy;
    const y1 = dir <= 1 ? cy + 1 : sy;
    this.scanNewAcrossLevels(s, k, ocx, ocy, cx, cy, x0, x1, y0, y1);
    for (let y = Math.max(0, y0); y <= Math.min(nyk - 1, y1); y++)
      for (let x = Math.max(0, x0); x <= Math.min(nxk - 1, x1); x++)
        this.scanCellObstacles(s, base + y * nxk + x);
    this.crossing(s, k, cx, cy);
    this.heap.set(s, Math.min(b.evTime[s] as number, b.crossTime[s] as number));
  }

  /**
   * After body s of level k moved from level k's cell (ocx, ocy) to (cx, cy), whose new strip of
   * neighbours is [x0, x1] x [y0, y1]: test it against the bodies that just became candidates
   * (grid.ts). Finer levels: the bodies under the strip. Coarser levels: only where its coarser
   * cell changed, the strip beside the new coarser cell.
   */
  protected scanNewAcrossLevels(
    s: number,
    k: number,
    ocx: number,
    ocy: number,
    cx: number,
    cy: number,
    x0: number,
    x1: number,
    y0: number,
    y1: number,
  ): void {
    for (const j of this.grid.occupied) {
      if (j <= k) {
        const sh = k - j;
        this.scanFiner(s, j, x0 << sh, ((x1 + 1) << sh) - 1, y0 << sh, ((y1 + 1) << sh) - 1, true);
        continue;
      }
      const sh = j - k;
      const X = cx >> sh;
      const Y = cy >> sh;
      const OX = ocx >> sh;
      const OY = ocy >> sh;
      if (X !== OX) {
        const col = X > OX ? X + 1 : X - 1;
        this.scanBlock(s, j, col, col, Y - 1, Y + 1, true);
      } else if (Y !== OY) {
        const row = Y > OY ? Y + 1 : Y - 1;
        this.scanBlock(s, j, X - 1, X + 1, row, row, true);
      }
    }
  }
}
