import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { GRID_SEGMENT_PAD } from "../tolerances.js";
import { Grid } from "./grid.js";
import { rasterizeSegment, segmentMeetsRect } from "./rasterize.js";

const INF = Number.POSITIVE_INFINITY;
/** Whether the segment meets the unit square [0, 1] x [0, 1], widened by pad. */
const unit = (x1: number, y1: number, x2: number, y2: number, pad = 0) =>
  segmentMeetsRect(x1, y1, x2, y2, 0, 1, 0, 1, pad);

describe("segmentMeetsRect", () => {
  it("a segment inside, crossing, or beside the rectangle", () => {
    expect(unit(0.2, 0.2, 0.8, 0.7)).toBe(true); // inside
    expect(unit(-1, 0.5, 2, 0.5)).toBe(true); // through, horizontal
    expect(unit(0.5, -1, 0.5, 2)).toBe(true); // through, vertical
    expect(unit(-1, -1, 2, 2)).toBe(true); // through the diagonal
    expect(unit(2, 0, 3, 1)).toBe(false); // to the right
    expect(unit(-1, 1.5, 1.5, 3)).toBe(false); // above, slanted
    expect(unit(-1, 0.5, -0.5, 0.5)).toBe(false); // stops short of it
  });

  it("passing just outside a corner misses, and `pad` widens the rectangle to catch it", () => {
    // the line x + y = 2 + 1e-12 passes a hair outside the corner (1, 1)
    expect(unit(0, 2 + 1e-12, 2 + 1e-12, 0)).toBe(false);
    expect(unit(0, 2 + 1e-12, 2 + 1e-12, 0, 1e-9)).toBe(true);
    // along a border: on it counts, a rounding outside it only with the pad
    expect(unit(-1, 1, 2, 1)).toBe(true);
    expect(unit(-1, 1 + 1e-15, 2, 1 + 1e-15)).toBe(false);
    expect(unit(-1, 1 + 1e-15, 2, 1 + 1e-15, 1e-9)).toBe(true);
  });

  it("a point (a segment of no length) meets the rectangle only when inside it", () => {
    expect(unit(0.5, 0.5, 0.5, 0.5)).toBe(true);
    expect(unit(1.5, 0.5, 1.5, 0.5)).toBe(false);
  });

  it("rectangles reaching to infinity (the grid's edge cells)", () => {
    expect(segmentMeetsRect(5, 5, 6, 6, 1, INF, 1, INF, 0)).toBe(true);
    expect(segmentMeetsRect(-5, 5, -6, 6, 1, INF, -INF, INF, 0)).toBe(false);
    expect(segmentMeetsRect(-1e300, 0, 1e300, 0, -INF, -1e299, -1, 1, 0)).toBe(true);
  });
});

/** Every cell of the segment's bounding box that segmentMeetsRect accepts (the plain scan). */
function everyCell(grid: Grid, x1: number, y1: number, x2: number, y2: number): number[] {
  const out: number[] = [];
  const pad = grid.w * GRID_SEGMENT_PAD;
  for (let cy = grid.row(Math.min(y1, y2)); cy <= grid.row(Math.max(y1, y2)); cy++)
    for (let cx = grid.column(Math.min(x1, x2)); cx <= grid.column(Math.max(x1, x2)); cx++) {
      const [rx0, rx1, ry0, ry1] = grid.cellRect(cx, cy);
      if (segmentMeetsRect(x1, y1, x2, y2, rx0, rx1, ry0, ry1, pad)) out.push(cy * grid.nx + cx, 7);
    }
  return out;
}

describe("rasterizeSegment", () => {
  it("registers a segment in the cells of the plain scan of its bounding box, row by row (fast-check)", () => {
    const seed = Number(process.env.FC_SEED ?? 20261124);
    console.log(`[rasterize] fast-check seed ${seed} (set FC_SEED to change)`);
    const grid = new Grid(1);
    // Ends anywhere, on cell corners (integers with w = 1 after the offset), or off the grid.
    const coord = fc.oneof(
      fc.double({ min: -5, max: 45, noNaN: true }),
      fc.integer({ min: -3, max: 43 }).map((k) => 0.5 + k * 0.75),
      fc.integer({ min: -3, max: 43 }).map((k) => 0.5 + k * 0.75 + 1e-12),
    );
    fc.assert(
      fc.property(coord, coord, coord, coord, (x1, y1, x2, y2) => {
        grid.reset(0.5, 0.5, 0.75, 40, 30);
        const out: number[] = [];
        rasterizeSegment(grid, x1, y1, x2, y2, 7, out);
        expect(out).toEqual(everyCell(grid, x1, y1, x2, y2));
      }),
      { seed, numRuns: 3000 },
    );
  });

  it("a long diagonal segment is registered in the cells along it only", () => {
    const grid = new Grid(1);
    grid.reset(0, 0, 1, 1000, 1000);
    const out: number[] = [];
    rasterizeSegment(grid, 0.5, 0.25, 999.5, 999.75, 7, out);
    // About two cells per column it crosses, not the 10^6 of its bounding box.
    expect(out.length / 2).toBeGreaterThan(999);
    expect(out.length / 2).toBeLessThan(2100);
    expect(out).toEqual(everyCell(grid, 0.5, 0.25, 999.5, 999.75));
  });
});
