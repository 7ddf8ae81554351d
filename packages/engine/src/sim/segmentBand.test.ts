// segmentXRange: the x extent of the part of a segment inside a horizontal band (the rows of the
// placement indexes), and placementPad.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { PLACEMENT_INDEX_PAD } from "../tolerances.js";
import { placementPad, segmentXRange } from "./segmentBand.js";

const range = (x1: number, y1: number, x2: number, y2: number, lo: number, hi: number) => {
  const out = [0, 0];
  return segmentXRange(x1, y1, x2, y2, lo, hi, out) ? out : null;
};

describe("segmentXRange", () => {
  it("clips a diagonal to the band, keeps a horizontal one whole or drops it, and takes a point", () => {
    expect(range(0, 0, 10, 10, 2, 4)).toEqual([2, 4]);
    expect(range(10, 0, 0, 10, 2, 4)).toEqual([6, 8]);
    expect(range(0, 0, 10, 10, 20, 30)).toBeNull();
    expect(range(-3, 5, 7, 5, 0, 5)).toEqual([-3, 7]);
    expect(range(-3, 5, 7, 5, 6, 9)).toBeNull();
    expect(range(2, 3, 2, 3, 3, 3)).toEqual([2, 2]);
    expect(range(0, 0, 4, 8, -Infinity, Infinity)).toEqual([0, 4]);
    expect(range(0, 0, 4, 8, -Infinity, 4)).toEqual([0, 2]);
  });

  it("holds every point of the segment inside the band, and says no only when none is (property)", () => {
    const c = fc.integer({ min: -64, max: 64 }).map((k) => k / 4);
    fc.assert(
      fc.property(c, c, c, c, c, c, (x1, y1, x2, y2, a, b) => {
        const lo = Math.min(a, b);
        const hi = Math.max(a, b);
        const out = range(x1, y1, x2, y2, lo, hi);
        for (let i = 0; i <= 64; i++) {
          const t = i / 64;
          const x = x1 + t * (x2 - x1);
          const y = y1 + t * (y2 - y1);
          if (y < lo || y > hi) continue;
          expect(out).not.toBeNull();
          const [xa, xb] = out as number[];
          expect(x).toBeGreaterThanOrEqual((xa as number) - 1e-12);
          expect(x).toBeLessThanOrEqual((xb as number) + 1e-12);
        }
        if (out !== null) {
          // and the range is no wider than the segment's part in the band
          expect(out[0]).toBeGreaterThanOrEqual(Math.min(x1, x2));
          expect(out[1]).toBeLessThanOrEqual(Math.max(x1, x2));
        }
      }),
      { seed: seedFor("segmentXRange"), numRuns: 500 },
    );
  });
});

describe("placementPad", () => {
  it("is PLACEMENT_INDEX_PAD times the sum of the magnitudes", () => {
    expect(placementPad(1e6, -2e6, 0, 3)).toBe(PLACEMENT_INDEX_PAD * (1e6 + 2e6 + 3));
    expect(placementPad(0, 0, 0, 0)).toBe(0);
  });
});
