import { describe, expect, it } from "vitest";
import { segmentMeetsRect } from "./rasterize.js";

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
