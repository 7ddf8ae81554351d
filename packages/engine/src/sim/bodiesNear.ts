/**
 * The bodies of the World's broad-phase grid (grid.ts, read only) near a segment or a point: the
 * candidates of a placement check when a line or point is added or moved, so that m obstacles
 * placed among n bodies cost about m + n tests, not m × n. At each level holding bodies it visits
 * the cells within reach of the segment (the level's largest radius, the segment's pad, and one more
 * cell, since a body's recorded cell may be one off its position by a crossing's rounding), row by
 * row (segmentBand.ts), or the level's bodies when they are fewer than those cells.
 */
import { mulPow2 } from "../roots/pow2.js";
import type { Grid } from "./grid.js";
import { placementPad, segmentXRange } from "./segmentBand.js";

const span = [0, 0];
/** Per row of a level, its first and last column (reused). */
const rows: number[] = [];

/** Call `visit` for every body (slot) of `grid` that could reach the segment (x1, y1)-(x2, y2) (a
 *  point when both ends are equal), and perhaps others; a body may be visited only once. */
export function forEachBodyNearSegment(
  grid: Grid,
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  visit: (s: number) => void,
): void {
  const pad = placementPad(x1, y1, x2, y2);
  for (const j of grid.occupied) {
    const members = grid.members[j] as number[];
    const nxj = grid.nxOf[j] as number;
    const nyj = grid.nyOf[j] as number;
    const wj = mulPow2(grid.w, j);
    const reach = (grid.fitR[j] as number) + pad + wj;
    const r0 = grid.row(Math.min(y1, y2) - reach) >> j;
    const r1 = grid.row(Math.max(y1, y2) + reach) >> j;
    let cells = 0;
    rows.length = 0;
    if (r1 - r0 < members.length)
      for (let cy = r0; cy <= r1 && cells <= members.length; cy++) {
        // the row's band (edge rows extend to infinity), widened by the reach
        const lo = cy === 0 ? -Infinity : grid.boundaryY(cy << j) - reach;
        const hi = cy === nyj - 1 ? Infinity : grid.boundaryY((cy + 1) << j) + reach;
        if (!segmentXRange(x1, y1, x2, y2, lo, hi, span)) continue;
        const c0 = grid.column((span[0] as number) - reach) >> j;
        const c1 = Math.min(nxj - 1, grid.column((span[1] as number) + reach) >> j);
        rows.push(cy, c0, c1);
        cells += c1 - c0 + 1;
      }
    if (r1 - r0 >= members.length || cells > members.length) {
      for (const s of members) visit(s);
      continue;
    }
    const base = grid.base[j] as number;
    for (let i = 0; i < rows.length; i += 3) {
      const at = base + (rows[i] as number) * nxj;
      for (let cx = rows[i + 1] as number; cx <= (rows[i + 2] as number); cx++)
        for (let s = grid.head[at + cx] as number; s >= 0; s = grid.next[s] as number) visit(s);
    }
  }
}
