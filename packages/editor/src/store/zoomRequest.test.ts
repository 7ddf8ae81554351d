import { describe, expect, it } from "vitest";
import { minSpan, zoomIn, zoomOut } from "./timeWindow";
import { wheelZoomFactor, zoomBy, zoomToSpan } from "./zoomRequest";

describe("zoom request: by a factor (the wheel)", () => {
  it("scales the span around the time, which keeps its place on the slider", () => {
    // t = 10 is a quarter of the way along [0, 40]: it stays a quarter of the way along [7.5, 17.5]
    expect(zoomBy(null, 1 / 4, 10, 40)).toEqual({ lo: 7.5, hi: 17.5 });
    expect(zoomBy({ lo: 7.5, hi: 17.5 }, 2, 10, 40)).toEqual({ lo: 5, hi: 25 });
    // 1/2 and 2 are the Zoom buttons' steps
    expect(zoomBy(null, 1 / 2, 12, 40)).toEqual(zoomIn(null, 12, 40));
    const w = { lo: 9, hi: 14 };
    expect(zoomBy(w, 2, 12, 40)).toEqual(zoomOut(w, 12, 40));
  });

  it("stays inside [0, end] and holds the time", () => {
    // zooming out near 0 or near the end shifts the window back inside the history
    expect(zoomBy({ lo: 1, hi: 11 }, 3, 2, 100)).toEqual({ lo: 0, hi: 30 });
    expect(zoomBy({ lo: 90, hi: 100 }, 3, 99, 100)).toEqual({ lo: 70, hi: 100 });
    for (const t of [0, 3, 50, 99.5, 100]) {
      const z = zoomBy({ lo: 0, hi: 100 - 1e-9 }, 1 / 1000, t, 100)!;
      expect(z.lo).toBeGreaterThanOrEqual(0);
      expect(z.hi).toBeLessThanOrEqual(100);
      expect(z.lo <= Math.min(t, z.hi) && Math.min(t, 100 - 1e-9) <= z.hi).toBe(true);
    }
    // zooming in stays inside the window, also one reaching past the history's end (a page turned
    // into the computation): the thumb keeps its place
    expect(zoomBy({ lo: 20, hi: 40 }, 1 / 2, 22, 25)).toEqual({ lo: 21, hi: 31 });
    // a time outside the window (being recomputed) zooms around the window's nearest end
    expect(zoomBy({ lo: 10, hi: 20 }, 1 / 2, 30, 100)).toEqual({ lo: 15, hi: 20 });
  });

  it("covering the history is the whole history; the whole history zooms out no further", () => {
    expect(zoomBy({ lo: 10, hi: 20 }, 4, 15, 40)).toBeNull();
    expect(zoomBy({ lo: 10, hi: 20 }, 64, 15, 40)).toBeNull();
    expect(zoomBy(null, 4, 15, 40)).toBeNull();
  });

  it("stops at the smallest span and gives back the same window when nothing changes", () => {
    // a billion seconds to the smallest span for its end (1e-12 of it) in one request, then for
    // the window's own end, around 5e8 (to the floating-point step of times near 5e8, 6e-8 s)
    const small = zoomBy(null, 1e-30, 5e8, 1e9)!;
    expect(small.hi - small.lo).toBeCloseTo(minSpan(1e9), 6);
    const tiny = zoomBy(small, 1e-30, 5e8, 1e9)!;
    expect(tiny.hi - tiny.lo).toBeCloseTo(minSpan(5e8), 6);
    expect(tiny.lo <= 5e8 && 5e8 <= tiny.hi).toBe(true);
    expect(zoomBy(tiny, 1 / 4, 5e8, 1e9)).toBe(tiny);
    // nothing to zoom into, a factor of 1 or one that is not a positive number
    expect(zoomBy(null, 1 / 4, 0, 0)).toBeNull();
    const w = { lo: 10, hi: 20 };
    for (const f of [1, 0, -2, Number.NaN, Number.POSITIVE_INFINITY]) expect(zoomBy(w, f, 15, 40)).toBe(w);
  });

  it("from a billion seconds to a few seconds in 14 wheel notches, the time in view all along", () => {
    const t = 1e9 - 123.4;
    let w = null as ReturnType<typeof zoomBy>;
    for (let i = 0; i < 14; i++) {
      w = zoomBy(w, wheelZoomFactor(-100), t, 1e9);
      expect(w!.lo <= t && t <= w!.hi).toBe(true);
    }
    expect(w!.hi - w!.lo).toBeCloseTo(1e9 / 4 ** 14, 9);
    expect(w!.hi - w!.lo).toBeLessThan(4);
  });
});

describe("zoom request: a typed width", () => {
  it("centres a window of that width on the time", () => {
    expect(zoomToSpan(null, 4, 1e9 - 100, 1e9)).toEqual({ lo: 1e9 - 102, hi: 1e9 - 98 });
    expect(zoomToSpan({ lo: 0, hi: 1 }, 2, 5, 40)).toEqual({ lo: 4, hi: 6 });
  });

  it("is shifted inside [0, end], and covering it is the whole history", () => {
    expect(zoomToSpan(null, 4, 1, 40)).toEqual({ lo: 0, hi: 4 });
    expect(zoomToSpan(null, 4, 39.5, 40)).toEqual({ lo: 36, hi: 40 });
    expect(zoomToSpan({ lo: 0, hi: 4 }, 40, 10, 40)).toBeNull();
    expect(zoomToSpan({ lo: 0, hi: 4 }, Number.POSITIVE_INFINITY, 10, 40)).toBeNull();
    // a time past the end (held there while the history is recomputed) counts as the end
    expect(zoomToSpan(null, 4, 90, 40)).toEqual({ lo: 36, hi: 40 });
  });

  it("is at least the smallest span; a width that is not positive changes nothing", () => {
    const z = zoomToSpan(null, 1e-20, 1e9 / 2, 1e9)!;
    expect(z.hi - z.lo).toBeCloseTo(minSpan(1e9 / 2), 6);
    expect(z.lo <= 1e9 / 2 && 1e9 / 2 <= z.hi).toBe(true);
    const w = { lo: 1, hi: 2 };
    for (const s of [0, -1, Number.NaN]) expect(zoomToSpan(w, s, 1.5, 40)).toBe(w);
    expect(zoomToSpan(w, 1, 1.5, 40)).toBe(w);
  });
});

describe("zoom request: the wheel's factor", () => {
  it("one notch up is 4x in, down 4x out; lines and pages count as pixels; at most 64x", () => {
    expect(wheelZoomFactor(-100)).toBe(1 / 4);
    expect(wheelZoomFactor(100)).toBe(4);
    expect(wheelZoomFactor(-3, 1)).toBeCloseTo(1 / 4, 12);
    expect(wheelZoomFactor(0)).toBe(1);
    expect(wheelZoomFactor(-10)).toBeCloseTo(4 ** -0.1, 12);
    expect(wheelZoomFactor(1, 2)).toBe(64);
    expect(wheelZoomFactor(-1e6)).toBe(1 / 64);
    expect(wheelZoomFactor(Number.NaN)).toBe(1);
  });
});
