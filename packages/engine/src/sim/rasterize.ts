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

/** Append (cell, code) pairs for every cell the segment passes through. */
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
  for (let cy = r0; cy <= r1; cy++) {
    for (let cx = c0; cx <= c1; cx++) {
      const [rx0, rx1, ry0, ry1] = grid.cellRect(cx, cy);
      if (segmentMeetsRect(x1, y1, x2, y2, rx0, rx1, ry0, ry1, pad)) out.push(cy * grid.nx + cx, code);
    }
  }
}
