/**
 * Whether a grid of several levels (grid.ts) pays for a scene's radii: a pure estimate of the
 * pair tests and cell visits one prediction costs, averaged over the bodies, with level-0 cells
 * of side w0 (levels above for larger discs) against one level of cells of side W that fit every
 * disc. Only speed depends on the answer, never a result.
 */

import { mulPow2 } from "../roots/pow2.js";
import {
  GRID_CELL_MARGIN,
  GRID_CELL_VISIT_COST,
  GRID_CROSSING_COST,
  GRID_LEVEL_GAIN,
  GRID_PREDICTION_COST,
  GRID_PREDICTIONS_PER_EVENT,
  GRID_SEGMENT_TEST_COST,
} from "../tolerances.js";

/** Ratio between the cell sides cheapestCell tries. */
const GRID_CELL_STEP = Math.sqrt(Math.SQRT2);

/**
 * Finest level k whose cells (side w0 * 2^k) fit a disc of radius r; `top` (a single cell, which
 * fits any disc) if none below it does.
 */
export function levelOfRadius(r: number, w0: number, top = 30): number {
  let k = 0;
  while (k < top && mulPow2(w0, k) < 2 * GRID_CELL_MARGIN * r) k++;
  return k;
}

/** The level of a single cell in a grid of nx * ny level-0 cells. */
export function singleCellLevel(nx: number, ny: number): number {
  let k = 0;
  while (((nx - 1) >> k) + 1 > 1 || ((ny - 1) >> k) + 1 > 1) k++;
  return k;
}

/**
 * Estimated cost of one prediction, in pair tests, for bodies of radii `radii` spread over `area`:
 * with levels from cells of side w0 (`levels` true), or one level of side W.
 */
export function predictionCost(
  radii: ArrayLike<number>,
  area: number,
  w0: number,
  W: number,
  levels: boolean,
  top = 30,
): number {
  const n = radii.length;
  if (n === 0) return 0;
  if (!levels) return (9 * W * W * n) / area + 9 * GRID_CELL_VISIT_COST;
  const counts: number[] = [];
  for (let i = 0; i < n; i++) {
    const k = levelOfRadius(radii[i] as number, w0, top);
    while (counts.length <= k) counts.push(0);
    counts[k] = (counts[k] as number) + 1;
  }
  let total = 0;
  for (let k = 0; k < counts.length; k++) {
    const nk = counts[k] as number;
    if (nk === 0) continue;
    let cost = 0;
    for (let j = 0; j < counts.length; j++) {
      const nj = counts[j] as number;
      if (nj === 0) continue;
      const m = Math.max(j, k);
      const side = mulPow2(w0, m);
      const block = j >= k ? 3 : mulPow2(3, k - j);
      const cells = block * block;
      // The single top cell holds everything: its discs are tested against every body.
      cost += m === top ? nj : Math.min(nj, (9 * side * side * nj) / area) + cells * GRID_CELL_VISIT_COST;
    }
    total += nk * cost;
  }
  return total / n;
}

/**
 * Whether levels from cells of side w0 (level `top` a single cell) cost at most GRID_LEVEL_GAIN of
 * one level of side W.
 */
export function levelsPay(radii: ArrayLike<number>, area: number, w0: number, W: number, top = 30): boolean {
  if (w0 >= W) return false;
  return (
    predictionCost(radii, area, w0, W, true, top) <=
    GRID_LEVEL_GAIN * predictionCost(radii, area, w0, W, false, top)
  );
}

/**
 * What the grid's layout decision knows of a scene: how many bodies, their radii (all of them, or
 * an even sample each standing for bodies / radii.length: the estimate is an average), the
 * static obstacles the grid registers in its cells (segments: how many and their total length;
 * points), and the box of `width` x `height` holding all of them. Lines and rays are tested by
 * every prediction whatever the grid, so they weigh on no layout and are left out.
 */
export interface SceneLoad {
  bodies: number;
  radii: ArrayLike<number>;
  segments: number;
  segmentLength: number;
  points: number;
  width: number;
  height: number;
}

/**
 * Estimated distance a body travels between two of its collisions: the box's area over the width
 * of what it can hit per unit of travel (another disc 2(r + r'), a segment of length l seen at a
 * random angle 2l/π + 2r, a point 2r), at the mean radius r; at most width + height, past which a
 * body leaves the box for an edge cell, where it crosses no more boundaries.
 */
export function meanFreePath(load: SceneLoad): number {
  const n = load.bodies;
  let sum = 0;
  for (let i = 0; i < load.radii.length; i++) sum += load.radii[i] as number;
  const r = load.radii.length > 0 ? sum / load.radii.length : 0;
  const width = (n - 1) * 4 * r + (2 * load.segmentLength) / Math.PI + 2 * r * (load.segments + load.points);
  const cap = load.width + load.height;
  return width > 0 ? Math.min(cap, (load.width * load.height) / width) : cap;
}

/**
 * Estimated pair tests (segments weighted by GRID_SEGMENT_TEST_COST) and cell visits in a block of
 * bx x by cells of side s, for bodies and obstacles spread evenly over the load's box: a segment
 * of length l meets a block when it passes within the block's Minkowski sum with it, of area
 * bx by s^2 + l s (bx + by) 2/π on average over its angle. Never more than the scene holds.
 */
function blockTests(load: SceneLoad, s: number, bx: number, by: number): number {
  const area = load.width * load.height;
  const block = bx * by * s * s;
  const bodies = Math.min(load.bodies, (block * load.bodies) / area);
  const segments = Math.min(
    load.segments,
    (block * load.segments + (2 / Math.PI) * s * (bx + by) * load.segmentLength) / area,
  );
  const points = Math.min(load.points, (block * load.points) / area);
  return bodies + GRID_SEGMENT_TEST_COST * segments + points + bx * by * GRID_CELL_VISIT_COST;
}

/**
 * Estimated cost of one collision, in pair tests, with level-0 cells of side w0 (each body in the
 * finest level that fits it, levels up to `top`) or a single cell (w0 = Infinity): the
 * GRID_PREDICTIONS_PER_EVENT predictions it makes (GRID_PREDICTION_COST plus a 3x3 block's
 * tests), and the cell crossings a body makes over a mean free path (4/π boundaries per cell side
 * travelled, each GRID_CROSSING_COST plus a strip of three cells' tests), averaged over the bodies.
 */
export function eventCost(load: SceneLoad, w0: number, top = 30): number {
  const n = load.radii.length;
  if (n === 0 || load.bodies === 0) return 0;
  if (w0 === Number.POSITIVE_INFINITY) {
    const all = load.bodies + GRID_SEGMENT_TEST_COST * load.segments + load.points + GRID_CELL_VISIT_COST;
    return GRID_PREDICTIONS_PER_EVENT * (GRID_PREDICTION_COST + all);
  }
  const path = meanFreePath(load);
  let total = 0;
  for (let i = 0; i < n; i++) {
    const k = levelOfRadius(load.radii[i] as number, w0, top);
    const s = mulPow2(w0, k);
    const crossings = k === top ? 0 : (4 / Math.PI) * (path / s);
    total +=
      GRID_PREDICTIONS_PER_EVENT * (GRID_PREDICTION_COST + blockTests(load, s, 3, 3)) +
      crossings * (GRID_CROSSING_COST + blockTests(load, s, 3, 1));
  }
  return total / n;
}

/**
 * The level-0 cell side from wMin up (steps of 2^(1/4)) to the load box's larger side that
 * minimises eventCost over a grid of the box `width` x `height` (the load's box padded), at most
 * `maxCells` level-0 cells; and that cost.
 */
export function cheapestCell(
  load: SceneLoad,
  width: number,
  height: number,
  wMin: number,
  maxCells: number,
): { w: number; cost: number } {
  let w = Math.max(wMin, Math.sqrt((width * height) / maxCells));
  let best = { w, cost: Number.POSITIVE_INFINITY };
  const last = Math.max(width, height);
  for (let i = 0; i < 200 && (i === 0 || w <= last); i++, w *= GRID_CELL_STEP) {
    const top = singleCellLevel(Math.ceil(width / w), Math.ceil(height / w));
    const cost = eventCost(load, w, top);
    if (cost < best.cost) best = { w, cost };
  }
  return best;
}
