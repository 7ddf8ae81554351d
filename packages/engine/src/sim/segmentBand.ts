/**
 * Pure geometry for the placement indexes (sim/obstacleCells.ts, sim/bodiesNear.ts,
 * scene/discGrid.ts): the cells a segment passes, row by row. `segmentXRange` gives the x extent of
 * the part of a segment that lies in a horizontal band, so a long diagonal segment costs the cells
 * along it, not its bounding box in cells. It is computed in doubles: callers widen the band and the
 * range by a pad far above its rounding (a few ulps of the coordinates, PLACEMENT_INDEX_PAD).
 */
import { PLACEMENT_INDEX_PAD } from "../tolerances.js";

/**
 * Whether the segment (x1, y1)-(x2, y2) (a point when both ends are equal) meets the band
 * ylo <= y <= yhi (either bound may be infinite); if it does, `out` gets the least and greatest x
 * of its part in the band.
 */
export function segmentXRange(
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  ylo: number,
  yhi: number,
  out: number[],
): boolean {
  const dy = y2 - y1;
  let t0 = 0;
  let t1 = 1;
  if (dy === 0) {
    if (y1 < ylo || y1 > yhi) return false;
  } else {
    let a = (ylo - y1) / dy;
    let b = (yhi - y1) / dy;
    if (a > b) [a, b] = [b, a];
    if (a > t0) t0 = a;
    if (b < t1) t1 = b;
    if (t0 > t1) return false;
  }
  const dx = x2 - x1;
  // the ends exactly, not x1 + dx (which may round past x2)
  const xa = t0 === 0 ? x1 : t0 === 1 ? x2 : x1 + dx * t0;
  const xb = t1 === 0 ? x1 : t1 === 1 ? x2 : x1 + dx * t1;
  out[0] = Math.min(xa, xb);
  out[1] = Math.max(xa, xb);
  return true;
}

/**
 * The pad of a box around these coordinates (the ends of a segment, or a disc's centre and radius):
 * PLACEMENT_INDEX_PAD times the sum of their magnitudes. An overlap test computed in doubles errs by
 * a few ulps of the coordinates it reads, so a pair it finds overlapping lies within the sum of the
 * two pads of overlapping for real, and boxes widened by their pads share a cell.
 */
export function placementPad(a: number, b: number, c: number, d: number): number {
  return PLACEMENT_INDEX_PAD * (Math.abs(a) + Math.abs(b) + Math.abs(c) + Math.abs(d));
}
