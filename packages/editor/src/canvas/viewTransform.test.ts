import { describe, expect, it } from "vitest";
import { fit, include, pan, toScreen, toWorld, zoomAt } from "./viewTransform";

const size = { width: 800, height: 600 };
const view = { cx: 10, cy: -5, scale: 3 };

describe("view transform", () => {
  it("toWorld inverts toScreen, and y points up in the world", () => {
    const [sx, sy] = toScreen(view, size, 12, 7);
    expect(toWorld(view, size, sx, sy)).toEqual([12, 7]);
    expect(toScreen(view, size, 10, 0)[1]).toBeLessThan(toScreen(view, size, 10, -1)[1]);
  });

  it("zoomAt keeps the world point under the cursor fixed", () => {
    const before = toWorld(view, size, 123, 456);
    const z = zoomAt(view, size, 123, 456, 1.7);
    expect(z.scale).toBeCloseTo(5.1, 12);
    const after = toWorld(z, size, 123, 456);
    expect(after[0]).toBeCloseTo(before[0], 9);
    expect(after[1]).toBeCloseTo(before[1], 9);
  });

  it("pan moves the content with the pointer", () => {
    const p = pan(view, 30, -60);
    const [sx, sy] = toScreen(p, size, 12, 7);
    const [sx0, sy0] = toScreen(view, size, 12, 7);
    expect(sx - sx0).toBeCloseTo(30, 9);
    expect(sy - sy0).toBeCloseTo(-60, 9);
  });

  it("fit shows the whole bounds inside the margins", () => {
    const b = include(include(null, -100, 0), 300, 50);
    const v = fit(b, size, 20);
    const [x0, y0] = toScreen(v, size, -100, 0);
    const [x1, y1] = toScreen(v, size, 300, 50);
    expect(x0).toBeCloseTo(20, 9);
    expect(x1).toBeCloseTo(780, 9);
    expect(y0).toBeLessThanOrEqual(580);
    expect(y1).toBeGreaterThanOrEqual(20);
  });

  it("fit of nothing or of a single point gives a usable view", () => {
    expect(fit(null, size)).toEqual({ cx: 0, cy: 0, scale: 1 });
    expect(fit(include(null, 5, 6), size)).toEqual({ cx: 5, cy: 6, scale: 1 });
  });

  it("fit with a minimum extent shows at least that many world units along the longer side", () => {
    const b = include(null, 0, 0, 1); // a disc of radius 1
    expect(fit(b, size, 20, 10)).toEqual({ cx: 0, cy: 0, scale: 76 });
    // bounds wider than the minimum are fitted as without it
    const wide = include(include(null, -100, 0), 300, 50);
    expect(fit(wide, size, 20, 10)).toEqual(fit(wide, size, 20));
  });
});
