/**
 * Which grid cells a static obstacle touches (pure geometry for the broad phase).
 * A disc touching a segment or a point has its centre within maxR of it, so registering each
 * obstacle in every cell it passes through lets the 3x3 neighbourhood scan find it.
 */
import { GRID_SEGMENT_PAD } from "../tolerances.js";
import type { Grid } from "./grid.js";

/**
 * Whether the segment (x1, y1)-(x2, y2) meets the rectangle [rx0, rx1] x [ry0, ry1] (which may be
 * infinite), by clipping the segment's parameter range against both slabs. `pad` widens the
 * rectangle so that a segment grazing a cell border is registered on both sides.
 */
export function segmentMeetsRect(
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  rx0: number,
  rx1: number,
  ry0: number,
  ry1: number,
  pad: number,
): boolean {
  let t0 = 0;
  let t1 = 1;
  const clip = (p: number, d: number, lo: number, hi: number): boolean => {
    if (d === 0) return p >= lo && p <= hi;
    let a = (lo - p) / d;
    let b = (hi - p) / d;
    if (a > b) [a, b] = [b, a];
    if (a > t0) t0 = a;
    if (b < t1) t1 = b;
    return t0 <= t1;
  };
  return clip(x1, x2 - x1, rx0 - pad, rx1 + pad) && clip(y1, y2 - y1, ry0 - pad, ry1 + pad);
}

/**
 * Append (cell, code) pairs for every cell the segment passes through. Row by row, only the
 * columns the segment spans within the row (one more each side for rounding) are tested, so a long
 * diagonal segment costs O(cells it crosses), not O(its bounding box in cells).
 */
export function rasterizeSegment(
  grid: Grid,
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  code: number,
  out: number[],
): void {
  const c0 = grid.column(Math.min(x1, x2));
  const c1 = grid.column(Math.max(x1, x2));
  const r0 = grid.row(Math.min(y1, y2));
  const r1 = grid.row(Math.max(y1, y2));
  const pad = grid.w * GRID_SEGMENT_PAD;
  const dy = y2 - y1;
  for (let cy = r0; cy <= r1; cy++) {
    let a = c0;
    let b = c1;
    if (dy !== 0 && c0 < c1) {
      // The segment's x at the row's (padded) bottom and top, clamped to its ends.
      const [, , ry0, ry1] = grid.cellRect(c0, cy);
      const t0 = Math.min(1, Math.max(0, (ry0 - pad - y1) / dy));
      const t1 = Math.min(1, Math.max(0, (ry1 + pad - y1) / dy));
      const xa = x1 + (x2 - x1) * t0;
      const xb = x1 + (x2 - x1) * t1;
      a = Math.max(c0, grid.column(Math.min(xa, xb)) - 1);
      b = Math.min(c1, grid.column(Math.max(xa, xb)) + 1);
    }
    for (let cx = a; cx <= b; cx++) {
      const [rx0, rx1, ry0, ry1] = grid.cellRect(cx, cy);
      if (segmentMeetsRect(x1, y1, x2, y2, rx0, rx1, ry0, ry1, pad)) out.push(cy * grid.nx + cx, code);
    }
  }
}
