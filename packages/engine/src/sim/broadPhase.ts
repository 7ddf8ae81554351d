/**
 * The broad phase's upkeep: building the grid (grid.ts) around the bodies' current positions,
 * registering each body in the level that fits its radius, registering obstacles in the cells they
 * touch, and visiting the bodies near a disc for placement checks. It never changes a motion: the
 * grid only decides which pairs are tested, so no result depends on it, only speed.
 */
import {
  GRID_CELL_MARGIN,
  GRID_CELLS_PER_BODY,
  GRID_CELLS_PER_ITEM,
  GRID_MIN_BODIES,
  GRID_OBSTACLE_GAIN,
} from "../tolerances.js";
import { cheapestCell, eventCost, levelsPay, type SceneLoad, singleCellLevel } from "./gridCost.js";
import { rasterizeSegment } from "./rasterize.js";
import { SimState } from "./state.js";

const INF = Number.POSITIVE_INFINITY;

/** Most radii the obstacle layout's cost estimate averages over (a rebuild stays O(bodies)). */
const GRID_RADII_SAMPLE = 256;

/** A grid layout: lower-left corner, level-0 cell side, columns, rows, the radius the side fits. */
type Layout = [number, number, number, number, number, number];

/** Grow box [minX, minY, maxX, maxY] to hold (x, y). */
function stretch(box: number[], x: number, y: number): void {
  box[0] = Math.min(box[0] as number, x);
  box[1] = Math.min(box[1] as number, y);
  box[2] = Math.max(box[2] as number, x);
  box[3] = Math.max(box[3] as number, y);
}

export class BroadPhase extends SimState {
  /**
   * Segments and points the grid's layout was computed (or last found right) for, and whether it
   * is the obstacle layout (obstacleUpkeep.ts keeps it while they stay near that number).
   */
  protected gridObstacles = 0;
  protected gridForObstacles = false;

  protected override copyInto(target: SimState): void {
    super.copyInto(target);
    (target as BroadPhase).gridObstacles = this.gridObstacles;
    (target as BroadPhase).gridForObstacles = this.gridForObstacles;
  }

  /**
   * Size the grid's and the queue's slot ranges to the body store's capacity (after it grew or was
   * trimmed): every per-slot array of the World is then as long as the store's.
   */
  protected followStore(): void {
    const capacity = this.store.capacity;
    if (this.grid.slotCapacity !== capacity) this.grid.resize(capacity);
    if (this.heap.slotCapacity !== capacity) this.heap.resize(capacity);
  }

  /**
   * Give back the slots the bodies no longer use (bodyStore.ts `trim`) and size the grid and the
   * queue to match. Only where every prediction is made again next (World's prepare step, before
   * the grid is rebuilt): a slot dropped here and taken again later is another body.
   */
  protected fitSlots(): void {
    if (this.store.trim()) this.followStore();
  }

  /** The level-0 cells the segment (x1, y1)-(x2, y2) (a point: both ends equal) is registered in. */
  protected cellsOfObstacle(x1: number, y1: number, x2: number, y2: number): number[] {
    const pairs: number[] = [];
    rasterizeSegment(this.grid, x1, y1, x2, y2, 0, pairs);
    const cells: number[] = [];
    for (let i = 0; i < pairs.length; i += 2) cells.push(pairs[i] as number);
    return cells;
  }

  /**
   * Rebuild the grid around the current positions (never changes a motion). A disc (ex, ey, er)
   * about to be added is included; while editing (`slack` > 1) the grid is made roomier so that
   * a stream of additions rebuilds it only O(log n) times; `advance` rebuilds it tight.
   *
   * The body layout (from GRID_MIN_BODIES bodies; a single cell below) weighs two options
   * (gridCost.ts): level-0 cells that fit the smallest disc, larger discs in coarser levels, so that
   * one radius-100 disc among thousands of radius 1 makes no cell 100 times too large, and neither
   * do a hundred of them; or cells that fit the largest disc. Either way cells are at least as large
   * as GRID_CELLS_PER_BODY cells per body allow, and the levels go up to a single cell, so a disc
   * that grows later has a level without a rebuild. When segments and points are many, the obstacle
   * layout covers them too, with the cell side that minimises the estimated cost of a collision
   * (tests saved against crossings added); it is taken when it costs at most GRID_OBSTACLE_GAIN of
   * the body layout.
   */
  protected rebuildGrid(ex = Number.NaN, ey = Number.NaN, er = 0, slack = 1): void {
    this.compactObstacles();
    const b = this.store;
    const extra = !Number.isNaN(ex);
    const radii: number[] = extra ? [er] : [];
    const box = extra ? [ex, ey, ex, ey] : [INF, INF, -INF, -INF];
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      radii.push(b.r[s] as number);
      stretch(box, this.xAt(s, this.now), this.yAt(s, this.now));
    }
    const n = radii.length;
    this.gridBodies = n;
    this.followStore();
    this.gridForObstacles = false;
    if (n === 0 || !this.opt.broadPhase) this.grid.reset(0, 0, 1, 1, 1);
    else {
      const [ox, oy, w, nx, ny, r, forObstacles] = this.chooseLayout(radii, box, slack);
      this.grid.reset(ox, oy, w, nx, ny, r);
      this.gridForObstacles = forObstacles;
    }
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      this.placeInGrid(s, this.xAt(s, this.now), this.yAt(s, this.now));
    }
    this.rasterizeObstacles();
    this.dirty = true;
  }

  /**
   * The cheaper of the body layout and the obstacle layout (see rebuildGrid) for bodies of these
   * radii in this box, and whether it is the obstacle layout.
   */
  protected chooseLayout(radii: number[], box: number[], slack: number): [...Layout, boolean] {
    let minR = INF;
    let maxR = 0;
    for (const r of radii) {
      minR = Math.min(minR, r);
      maxR = Math.max(maxR, r);
    }
    const n = radii.length;
    // Cells of side at least 2 r (times slack and margin) over the box padded (roomier while
    // editing), at most maxCells of them.
    const layout = (bx: number[], r: number, maxCells: number, wAtLeast = 0): Layout => {
      let w = Math.max(2 * r * slack * GRID_CELL_MARGIN, wAtLeast);
      const padX = slack > 1 ? Math.max(0.5 * slack * ((bx[2] as number) - (bx[0] as number)), 2 * w) : 2 * w;
      const padY = slack > 1 ? Math.max(0.5 * slack * ((bx[3] as number) - (bx[1] as number)), 2 * w) : 2 * w;
      const width = (bx[2] as number) - (bx[0] as number) + 2 * padX;
      const height = (bx[3] as number) - (bx[1] as number) + 2 * padY;
      if ((width / w) * (height / w) > maxCells) w = Math.sqrt((width * height) / maxCells);
      const nx = Math.max(1, Math.min(maxCells, Math.ceil(width / w)));
      const ny = Math.max(1, Math.min(maxCells, Math.ceil(height / w)));
      return [(bx[0] as number) - padX, (bx[1] as number) - padY, w, nx, ny, r];
    };
    let body: Layout = [0, 0, 1, 1, 1, 0];
    let forObstacles = false;
    if (n >= GRID_MIN_BODIES) {
      const maxCells = Math.max(16, GRID_CELLS_PER_BODY * n);
      const one = layout(box, maxR, maxCells);
      const fine = layout(box, minR, maxCells);
      const area = one[3] * one[2] * (one[4] * one[2]);
      const top = singleCellLevel(fine[3], fine[4]);
      body = levelsPay(radii, area, fine[2], one[2], top) ? fine : one;
      // Level 0 fits the largest disc whenever its side is the one sized for it.
      if (body[2] === one[2]) body[5] = maxR;
    }
    const load = this.obstacleLoad(radii, box);
    if (load !== undefined) {
      const [all, scene] = load;
      const single = body[3] === 1 && body[4] === 1;
      const bodyCost = eventCost(scene, single ? INF : body[2], singleCellLevel(body[3], body[4]));
      const maxCells = Math.max(16, GRID_CELLS_PER_ITEM * (n + scene.segments + scene.points));
      // Cells at least as large as the smallest or the largest disc needs: the cheaper.
      let best: Layout | undefined;
      let bestCost = INF;
      for (const r of minR < maxR ? [minR, maxR] : [maxR]) {
        const wide = layout(all, r, maxCells);
        const { w, cost } = cheapestCell(scene, wide[3] * wide[2], wide[4] * wide[2], wide[2], maxCells);
        if (cost < bestCost) {
          best = layout(all, r, maxCells, w);
          bestCost = cost;
        }
      }
      if (best !== undefined && bestCost <= GRID_OBSTACLE_GAIN * bodyCost) {
        body = best;
        forObstacles = true;
      }
    }
    return [...body, forObstacles];
  }

  /**
   * The box of bodies and obstacles (segments and points; lines and rays are global) and what the
   * cost model needs of them, or undefined when there is no segment or point.
   */
  private obstacleLoad(radii: number[], bodyBox: number[]): [number[], SceneLoad] | undefined {
    const all = bodyBox.slice();
    let segments = 0;
    let segmentLength = 0;
    for (const line of this.lineList) {
      if (line.kind !== "segment") continue;
      segments++;
      const dx = line.x2 - line.x1;
      const dy = line.y2 - line.y1;
      segmentLength += Math.sqrt(dx * dx + dy * dy);
      stretch(all, line.x1, line.y1);
      stretch(all, line.x2, line.y2);
    }
    for (const p of this.pointList) stretch(all, p.x, p.y);
    const points = this.pointList.length;
    if (segments + points === 0) return undefined;
    // A box at least a few diameters wide each way (bodies and obstacles on one line have no area).
    let maxR = 0;
    for (const r of radii) maxR = Math.max(maxR, r);
    const width = Math.max((all[2] as number) - (all[0] as number), 4 * maxR);
    const height = Math.max((all[3] as number) - (all[1] as number), 4 * maxR);
    // The estimate averages over the bodies: an even sample of their radii does as well.
    const step = Math.ceil(radii.length / GRID_RADII_SAMPLE);
    const sample = step > 1 ? radii.filter((_, i) => i % step === 0) : radii;
    return [all, { bodies: radii.length, radii: sample, segments, segmentLength, points, width, height }];
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
    this.gridObstacles = this.lineList.length - global.length + this.pointList.length;
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
