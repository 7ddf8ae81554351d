/**
 * Whether a grid of several levels (grid.ts) pays for a scene's radii: a pure estimate of the
 * pair tests and cell visits one prediction costs, averaged over the bodies, with level-0 cells
 * of side w0 (levels above for larger discs) against one level of cells of side W that fit every
 * disc. Only speed depends on the answer, never a result.
 */

import { mulPow2 } from "../roots/pow2.js";
import { GRID_CELL_MARGIN, GRID_CELL_VISIT_COST, GRID_LEVEL_GAIN } from "../tolerances.js";

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
