import { describe, expect, it } from "vitest";
import { emptyRect, fillRgb, type PixelRect, strokeRing } from "./ringRaster";

const W = 24;
const H = 20;
const buffer = () => new Uint8ClampedArray(W * H * 4);
const alpha = (px: Uint8ClampedArray, x: number, y: number) => px[4 * (y * W + x) + 3]!;

/** Pixels with some coverage, as [x, y, alpha]. */
function covered(px: Uint8ClampedArray): [number, number, number][] {
  const out: [number, number, number][] = [];
  for (let y = 0; y < H; y++)
    for (let x = 0; x < W; x++) if (alpha(px, x, y) > 0) out.push([x, y, alpha(px, x, y)]);
  return out;
}

describe("strokeRing", () => {
  it("covers the pixels one pixel wide around the circle, not its inside or beyond", () => {
    const px = buffer();
    const touched = emptyRect();
    strokeRing(px, W, H, 10.5, 10.5, 5, touched);
    expect(alpha(px, 15, 10)).toBe(255); // pixel centre (15.5, 10.5): on the circle
    expect(alpha(px, 14, 10)).toBe(0); // one pixel inside
    expect(alpha(px, 16, 10)).toBe(0); // one pixel outside
    expect(alpha(px, 10, 10)).toBe(0);
    for (const [x, y] of covered(px)) {
      const d = Math.hypot(x - 10, y - 10);
      expect(Math.abs(d - 5)).toBeLessThan(1);
      expect(x >= touched.minX && x < touched.maxX && y >= touched.minY && y < touched.maxY).toBe(true);
    }
    // a one-pixel-wide stroke covers about its length in pixels
    const total = covered(px).reduce((s, [, , a]) => s + a / 255, 0);
    expect(total).toBeGreaterThan(0.95 * 2 * Math.PI * 5);
    expect(total).toBeLessThan(1.05 * 2 * Math.PI * 5);
  });

  it("places the ring at its exact centre (no rounding to pixels)", () => {
    const centroid = (cx: number) => {
      const px = buffer();
      strokeRing(px, W, H, cx, 10, 3, emptyRect());
      let s = 0;
      let sx = 0;
      for (const [x, , a] of covered(px)) {
        s += a;
        sx += a * (x + 0.5);
      }
      return sx / s;
    };
    for (const cx of [10, 10.25, 10.6]) expect(Math.abs(centroid(cx) - cx)).toBeLessThan(0.1);
    expect(centroid(10.25)).toBeGreaterThan(centroid(10) + 0.15);
    expect(centroid(10.6)).toBeGreaterThan(centroid(10.25) + 0.2);
  });

  it("a disc smaller than a pixel still shows (a radius of half a pixel)", () => {
    const px = buffer();
    strokeRing(px, W, H, 5.5, 5.5, 0.5, emptyRect());
    expect(alpha(px, 5, 5)).toBe(128);
    expect(covered(px).length).toBeGreaterThan(1);
  });

  it("clips at the buffer's edges without wrapping into other rows", () => {
    const px = buffer();
    const touched = emptyRect();
    strokeRing(px, W, H, -2, 5, 4, touched);
    strokeRing(px, W, H, W + 1, 18, 4, touched);
    const xs = covered(px).map(([x]) => x);
    expect(xs.length).toBeGreaterThan(0);
    for (const x of xs) expect(x < 3 || x > W - 6).toBe(true);
    expect(touched).toEqual({ minX: 0, minY: 0, maxX: W, maxY: H });
    const none: PixelRect = emptyRect();
    strokeRing(px, W, H, -10, -10, 3, none);
    expect(none).toEqual(emptyRect());
  });

  it("composites overlapping rings (source over), leaving colour channels alone", () => {
    const px = buffer();
    strokeRing(px, W, H, 10, 10, 4, emptyRect());
    const once = Array.from(px);
    strokeRing(px, W, H, 10, 10, 4, emptyRect());
    for (let i = 3; i < px.length; i += 4) {
      const a = once[i]! / 255;
      expect(Math.abs(px[i]! - 255 * (1 - (1 - a) * (1 - a)))).toBeLessThanOrEqual(1);
    }
    for (let i = 0; i < px.length; i++) if (i % 4 !== 3) expect(px[i]).toBe(0);
  });
});

describe("fillRgb", () => {
  it("sets the colour with alpha 0 in the rectangle only", () => {
    const px = buffer();
    px.fill(7);
    fillRgb(px, W, { minX: 2, minY: 3, maxX: 5, maxY: 4 }, 10, 20, 30);
    expect(Array.from(px.subarray(4 * (3 * W + 2), 4 * (3 * W + 5)))).toEqual([
      10, 20, 30, 0, 10, 20, 30, 0, 10, 20, 30, 0,
    ]);
    expect(px[4 * (3 * W + 1)]).toBe(7);
    expect(px[4 * (3 * W + 5)]).toBe(7);
    expect(px[4 * (4 * W + 2)]).toBe(7);
  });
});
