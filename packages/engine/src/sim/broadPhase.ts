/**
 * The broad phase's upkeep: building the grid (grid.ts) around the bodies' current positions,
 * registering each body in the level that fits its radius, registering obstacles in the cells they
 * touch, and visiting the bodies near a disc for placement checks. It never changes a motion: the
 * grid only decides which pairs are tested, so no result depends on it, only speed.
 */
import { GRID_CELL_MARGIN, GRID_CELLS_PER_BODY, GRID_MIN_BODIES } from "../tolerances.js";
import { levelsPay, singleCellLevel } from "./gridCost.js";
import { rasterizeSegment } from "./rasterize.js";
import { SimState } from "./state.js";

const INF = Number.POSITIVE_INFINITY;

export class BroadPhase extends SimState {
  /**
   * Rebuild the grid around the current positions (never changes a motion). A disc (ex, ey, er)
   * about to be added is included; while editing (`slack` > 1) the grid is made roomier so that
   * a stream of additions rebuilds it only O(log n) times; `advance` rebuilds it tight.
   *
   * Two layouts are weighed (gridCost.ts): level-0 cells that fit the smallest disc, larger discs
   * in coarser levels, so that one radius-100 disc among thousands of radius 1 makes no cell 100
   * times too large, and neither do a hundred of them; or cells that fit the largest disc. Either
   * way cells are at least as large as GRID_CELLS_PER_BODY cells per body allow, and the levels go
   * up to a single cell, so a disc that grows later has a level without a rebuild.
   */
  protected rebuildGrid(ex = Number.NaN, ey = Number.NaN, er = 0, slack = 1): void {
    const b = this.store;
    const extra = !Number.isNaN(ex);
    const radii: number[] = extra ? [er] : [];
    let minX = extra ? ex : INF;
    let minY = extra ? ey : INF;
    let maxX = extra ? ex : -INF;
    let maxY = extra ? ey : -INF;
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      const x = this.xAt(s, this.now);
      const y = this.yAt(s, this.now);
      radii.push(b.r[s] as number);
      minX = Math.min(minX, x);
      maxX = Math.max(maxX, x);
      minY = Math.min(minY, y);
      maxY = Math.max(maxY, y);
    }
    const n = radii.length;
    this.gridBodies = n;
    this.grid.reserve(b.capacity);
    this.heap.reserve(b.capacity);
    if (n < GRID_MIN_BODIES || !this.opt.broadPhase) {
      this.grid.reset(0, 0, 1, 1, 1);
    } else {
      let minR = INF;
      let maxR = 0;
      for (const r of radii) {
        minR = Math.min(minR, r);
        maxR = Math.max(maxR, r);
      }
      const layout = (r: number): [number, number, number, number, number] => {
        let w = 2 * r * slack * GRID_CELL_MARGIN;
        // Leave room around the bodies so that edits nearby do not force a rebuild.
        const padX = slack > 1 ? Math.max(0.5 * slack * (maxX - minX), 2 * w) : 2 * w;
        const padY = slack > 1 ? Math.max(0.5 * slack * (maxY - minY), 2 * w) : 2 * w;
        const width = maxX - minX + 2 * padX;
        const height = maxY - minY + 2 * padY;
        const maxCells = Math.max(16, GRID_CELLS_PER_BODY * n);
        if ((width / w) * (height / w) > maxCells) w = Math.sqrt((width * height) / maxCells);
        const nx = Math.max(1, Math.min(maxCells, Math.ceil(width / w)));
        const ny = Math.max(1, Math.min(maxCells, Math.ceil(height / w)));
        return [minX - padX, minY - padY, w, nx, ny];
      };
      const one = layout(maxR);
      const fine = layout(minR);
      const area = one[3] * one[2] * (one[4] * one[2]);
      const top = singleCellLevel(fine[3], fine[4]);
      const [ox, oy, w, nx, ny] = levelsPay(radii, area, fine[2], one[2], top) ? fine : one;
      this.grid.reset(ox, oy, w, nx, ny, w === one[2] ? maxR : minR);
    }
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      this.placeInGrid(s, this.xAt(s, this.now), this.yAt(s, this.now));
    }
    this.rasterizeObstacles();
    this.dirty = true;
  }

  /** Put body s (not in the grid yet), now at (x, y), in its cell at the level that fits it. */
  protected placeInGrid(s: number, x: number, y: number): void {
    const g = this.grid;
    const k = g.levelFor(this.store.r[s] as number);
    g.enter(s, k, g.cellAt(k, g.column(x), g.row(y)));
  }

  /** Take body s out of the grid. */
  protected takeFromGrid(s: number): void {
    this.grid.leave(s);
  }

  /** Register segments and points in the grid cells they pass through; lines and rays stay global. */
  protected rasterizeObstacles(): void {
    const pairs: number[] = [];
    const global: number[] = [];
    this.lineList.forEach((line, i) => {
      if (line.kind === "segment") rasterizeSegment(this.grid, line.x1, line.y1, line.x2, line.y2, i, pairs);
      else global.push(i);
    });
    this.pointList.forEach((p, i) => {
      rasterizeSegment(this.grid, p.x, p.y, p.x, p.y, -(i + 1), pairs);
    });
    this.grid.setObstacles(pairs);
    this.globalLines = global;
    this.obstStamp = new Int32Array(this.lineList.length + this.pointList.length);
    this.stamp = 0;
  }

  /**
   * Call `visit` for every body registered near a disc of radius r at (x, y): every body it could
   * touch before either crosses a cell boundary (the scan `predict` makes, for placement checks).
   */
  protected forEachNear(x: number, y: number, r: number, visit: (s: number) => void): void {
    const g = this.grid;
    const k = g.levelFor(r);
    const cx = g.column(x) >> k;
    const cy = g.row(y) >> k;
    for (const j of g.occupied) {
      // Level j's cells under the 3x3 block around (cx, cy) at level max(j, k).
      const m = Math.max(j, k);
      const bx = j <= k ? cx : cx >> (j - k);
      const by = j <= k ? cy : cy >> (j - k);
      const sh = m - j;
      const nxj = g.nxOf[j] as number;
      const nyj = g.nyOf[j] as number;
      const x0 = Math.max(0, (bx - 1) << sh);
      const x1 = Math.min(nxj - 1, ((bx + 2) << sh) - 1);
      const y0 = Math.max(0, (by - 1) << sh);
      const y1 = Math.min(nyj - 1, ((by + 2) << sh) - 1);
      const base = g.base[j] as number;
      for (let yy = y0; yy <= y1; yy++)
        for (let xx = x0; xx <= x1; xx++)
          for (let s = g.head[base + yy * nxj + xx] as number; s >= 0; s = g.next[s] as number) visit(s);
    }
  }
}
