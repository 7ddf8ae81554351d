import { describe, expect, it } from "vitest";
import {
  canZoomIn,
  fitInside,
  follow,
  minSpan,
  settle,
  sliderTime,
  timeInWindow,
  viewRange,
  windowDigits,
  windowLabel,
  zoomIn,
  zoomOut,
} from "./timeWindow";

describe("time window: zoom", () => {
  it("the whole history (null) spans [0, horizon]; a window spans itself", () => {
    expect(viewRange(null, 40)).toEqual({ lo: 0, hi: 40 });
    expect(viewRange({ lo: 5, hi: 10 }, 40)).toEqual({ lo: 5, hi: 10 });
  });

  it("zoom in halves the span around the time, which keeps its place on the slider", () => {
    // t = 10 is a quarter of the way along [0, 40]: it stays a quarter of the way along [5, 25]
    expect(zoomIn(null, 10, 40)).toEqual({ lo: 5, hi: 25 });
    expect(zoomIn({ lo: 5, hi: 25 }, 10, 40)).toEqual({ lo: 7.5, hi: 17.5 });
    // at an end the window keeps that end
    expect(zoomIn(null, 0, 40)).toEqual({ lo: 0, hi: 20 });
    expect(zoomIn(null, 40, 40)).toEqual({ lo: 20, hi: 40 });
    // a time outside the window (the history being recomputed) zooms around the nearest end
    expect(zoomIn({ lo: 5, hi: 25 }, 30, 40)).toEqual({ lo: 15, hi: 25 });
  });

  it("zoom out doubles the span around the time, inside the history, and ends on the whole history", () => {
    expect(zoomOut({ lo: 7.5, hi: 17.5 }, 10, 40)).toEqual({ lo: 5, hi: 25 });
    // shifted back inside [0, end] when it would start before 0
    expect(zoomOut({ lo: 1, hi: 11 }, 10, 40)).toEqual({ lo: 0, hi: 20 });
    // or end past the history
    expect(zoomOut({ lo: 32, hi: 40 }, 39, 40)).toEqual({ lo: 24, hi: 40 });
    // covering the history (or more) is the whole history
    expect(zoomOut({ lo: 5, hi: 25 }, 10, 40)).toBeNull();
    expect(zoomOut({ lo: 0, hi: 30 }, 10, 40)).toBeNull();
    expect(zoomOut(null, 10, 40)).toBeNull();
  });

  it("zooming in and out again around the same time gives back the window", () => {
    let w = zoomIn(zoomIn(zoomIn(null, 1e9 - 3, 1e9), 1e9 - 3, 1e9), 1e9 - 3, 1e9);
    expect(w!.hi - w!.lo).toBe(1.25e8);
    w = zoomOut(zoomOut(zoomOut(w, 1e9 - 3, 1e9), 1e9 - 3, 1e9), 1e9 - 3, 1e9);
    expect(w).toBeNull();
    const a = zoomIn(zoomIn(null, 12, 40), 12, 40);
    expect(zoomOut(zoomIn(a, 12, 40), 12, 40)).toEqual(a);
  });

  it("zoom in stops at the smallest span and on an empty history", () => {
    expect(canZoomIn(null, 0)).toBe(false);
    expect(zoomIn(null, 0, 0)).toBeNull();
    const tiny = { lo: 1e9, hi: 1e9 + 1.5 * minSpan(1e9) };
    expect(canZoomIn(tiny, 2e9)).toBe(false);
    expect(zoomIn(tiny, 1e9, 2e9)).toBe(tiny);
    // halving a billion seconds 60 times stops at about a millisecond (thousands of
    // floating-point steps), around the time
    let w = zoomIn(null, 5e8, 1e9);
    for (let i = 0; i < 60; i++) w = zoomIn(w, 5e8, 1e9);
    expect(zoomIn(w, 5e8, 1e9)).toBe(w);
    expect(w!.hi - w!.lo).toBeGreaterThan(minSpan(1e9) / 2);
    expect(w!.lo).toBeLessThanOrEqual(5e8);
    expect(w!.hi).toBeGreaterThanOrEqual(5e8);
  });
});

describe("time window: the slider's value", () => {
  it("is the time, clamped to the slider's range (a value read just past an end stays at it)", () => {
    const w = { lo: 2.4995, hi: 2.5004999999999997 };
    expect(sliderTime(2.5005, w, 10)).toBe(w.hi);
    expect(sliderTime(2.4994999999999, w, 10)).toBe(w.lo);
    expect(sliderTime(2.5001, w, 10)).toBe(2.5001);
    expect(sliderTime(10.000000000000002, null, 10)).toBe(10);
    expect(sliderTime(3, null, 0)).toBe(0);
  });
});

describe("time window: following the time", () => {
  const w = { lo: 10, hi: 20 };

  it("a time inside the window leaves it as it is (the same object)", () => {
    for (const t of [10, 15, 20]) expect(follow(w, t, 100)).toBe(w);
    expect(follow(null, 500, 100)).toBeNull();
  });

  it("a time running off an edge turns to the next page of the same span", () => {
    expect(follow(w, 20.01, 100)).toEqual({ lo: 20, hi: 30 });
    expect(follow(w, 30, 100)).toEqual({ lo: 20, hi: 30 });
    expect(follow(w, 9.99, 100)).toEqual({ lo: 0, hi: 10 });
    expect(follow({ lo: 30, hi: 40 }, 25, 100)).toEqual({ lo: 20, hi: 30 });
  });

  it("a jump of more than a page centres the window on the time", () => {
    expect(follow(w, 55, 100)).toEqual({ lo: 50, hi: 60 });
    expect(follow({ lo: 50, hi: 60 }, 12, 100)).toEqual({ lo: 7, hi: 17 });
  });

  it("the window is shifted back inside the history", () => {
    // a page past the end of the history ends at its end
    expect(follow(w, 24, 25)).toEqual({ lo: 15, hi: 25 });
    // a jump to the end (a typed far time) shows the last span
    expect(follow(w, 1e9, 1e9)).toEqual({ lo: 1e9 - 10, hi: 1e9 });
    expect(follow({ lo: 50, hi: 60 }, 2, 100)).toEqual({ lo: 0, hi: 10 });
    // a time past the end of the history counts as its end
    expect(follow(w, 90, 50)).toEqual({ lo: 40, hi: 50 });
  });

  it("while the history grows, a page turned forward is whole (its part past the end is computed as time runs)", () => {
    // playing into the computation: [20, 40] though the history ends at 22 (shifted back: [2, 22])
    expect(follow({ lo: 0, hi: 20 }, 20.5, 22, true)).toEqual({ lo: 20, hi: 40 });
    expect(follow({ lo: 0, hi: 20 }, 20.5, 22)).toEqual({ lo: 2, hi: 22 });
    // the time kept at the end of the history while it is computed: the same page
    expect(follow({ lo: 20, hi: 40 }, 22, 22, true)).toEqual({ lo: 20, hi: 40 });
    // a jump, or a page turned backwards, is shifted inside the history as before
    expect(follow({ lo: 0, hi: 10 }, 35, 35, true)).toEqual({ lo: 25, hi: 35 });
    expect(follow({ lo: 5, hi: 15 }, 4, 35, true)).toEqual({ lo: 0, hi: 10 });
  });

  it("a history ending before the window is the whole history, as is a page no shorter than it", () => {
    expect(follow(w, 0, 5)).toBeNull();
    expect(follow(w, 0, 0)).toBeNull();
    expect(follow({ lo: 5, hi: 15 }, 2, 9)).toBeNull();
  });

  it("a history cut inside the window (an edit in the past) keeps it while it holds the time", () => {
    expect(follow(w, 12, 15)).toBe(w);
    expect(follow({ lo: 0, hi: 10 }, 0, 0)).toEqual({ lo: 0, hi: 10 });
  });

  it("once the history stops growing, a page reaching past its end settles back inside it; the time stays in it", () => {
    // a page turned into the computation, which stopped at 26: [16, 26], t = 23 still on it
    expect(settle({ lo: 20, hi: 30 }, 23, 26)).toEqual({ lo: 16, hi: 26 });
    // the whole history when the page is no shorter than it
    expect(settle({ lo: 10, hi: 40 }, 12, 25)).toBeNull();
    // a window inside the history, a time off the window or held past the end: the same window
    const inside = { lo: 10, hi: 20 };
    expect(settle(inside, 15, 20)).toBe(inside);
    const past = { lo: 20, hi: 30 };
    expect(settle(past, 19, 26)).toBe(past);
    expect(settle(past, 27, 26)).toBe(past);
    expect(settle(null, 5, 26)).toBeNull();
  });

  it("fitInside shifts a window into [0, end], or gives the whole history", () => {
    expect(fitInside(-3, 10, 40)).toEqual({ lo: 0, hi: 10 });
    expect(fitInside(35, 10, 40)).toEqual({ lo: 30, hi: 40 });
    expect(fitInside(5, 40, 40)).toBeNull();
  });
});

describe("time window: label", () => {
  it("writes 6 significant digits, more when the window is narrow for its times", () => {
    expect(windowLabel({ lo: 12.5, hi: 25 })).toBe("12.5–25");
    expect(windowLabel({ lo: 0, hi: 1 / 3 })).toBe("0–0.333333");
    expect(windowLabel({ lo: 1e9 - 0.5, hi: 1e9 + 0.5 })).toBe("999999999.5–1000000000.5");
  });
});

describe("time window: the time's precision", () => {
  const short = (x: number) => `short ${x}`;

  it("while zoomed the time is written to the window's precision, else in the short form", () => {
    // 6 significant digits read 1e+9 for every time of a few seconds around 1e9
    expect(timeInWindow(1e9 + 2.3456789, { lo: 1e9, hi: 1e9 + 4 }, short)).toBe("1000000002.346");
    // at most 15 digits (about the floating-point step there)
    expect(timeInWindow(1e9 - 2.3456789e-4, { lo: 1e9 - 1e-3, hi: 1e9 }, short)).toBe("999999999.999765");
    expect(timeInWindow(12.3456789, { lo: 0, hi: 40 }, short)).toBe("12.3457");
    expect(timeInWindow(12.3456789, { lo: 12.3, hi: 12.4 }, short)).toBe("12.34568");
    expect(timeInWindow(12.3456789, null, short)).toBe("short 12.3456789");
    expect(timeInWindow(0, { lo: 0, hi: 1e-6 }, short)).toBe("short 0");
    expect(windowDigits({ lo: 1e9, hi: 1e9 + 4 })).toBe(12);
    expect(windowDigits({ lo: 1e9, hi: 1e9 + 4 }, 4)).toBe(13);
    expect(windowDigits({ lo: 0, hi: 0 })).toBe(6);
    expect(windowDigits({ lo: 1e15, hi: 1e15 + 1 })).toBe(15);
  });
});
