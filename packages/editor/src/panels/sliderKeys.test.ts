import { describe, expect, it } from "vitest";
import { sliderKeyTime } from "./sliderKeys";

describe("the Time slider's keys while zoomed", () => {
  const w = { lo: 20, hi: 30 };

  it("arrows move by a hundredth of the window, page keys by a tenth, also past its edges", () => {
    expect(sliderKeyTime("ArrowRight", 25, w, 100)).toBeCloseTo(25.1, 12);
    expect(sliderKeyTime("ArrowUp", 25, w, 100)).toBeCloseTo(25.1, 12);
    expect(sliderKeyTime("ArrowLeft", 25, w, 100)).toBeCloseTo(24.9, 12);
    expect(sliderKeyTime("ArrowDown", 25, w, 100)).toBeCloseTo(24.9, 12);
    expect(sliderKeyTime("PageUp", 25, w, 100)).toBe(26);
    expect(sliderKeyTime("PageDown", 25, w, 100)).toBe(24);
    // at an edge the time moves on past it (the guard then turns the page)
    expect(sliderKeyTime("ArrowRight", 30, w, 100)).toBeCloseTo(30.1, 12);
    expect(sliderKeyTime("PageDown", 20, w, 100)).toBe(19);
  });

  it("stays within the history", () => {
    expect(sliderKeyTime("ArrowRight", 30, w, 30)).toBe(30);
    expect(sliderKeyTime("PageUp", 29.5, w, 30)).toBe(30);
    expect(sliderKeyTime("PageDown", 0.5, { lo: 0, hi: 10 }, 30)).toBe(0);
  });

  it("starts from the thumb: a time held past the window counts as its edge", () => {
    expect(sliderKeyTime("ArrowLeft", 35, w, 40)).toBeCloseTo(29.9, 12);
  });

  it("leaves Home, End, other keys and the whole history to the input", () => {
    expect(sliderKeyTime("Home", 25, w, 100)).toBeNull();
    expect(sliderKeyTime("End", 25, w, 100)).toBeNull();
    expect(sliderKeyTime("a", 25, w, 100)).toBeNull();
    expect(sliderKeyTime("ArrowRight", 25, null, 100)).toBeNull();
  });
});
