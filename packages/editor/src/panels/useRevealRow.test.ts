import { describe, expect, it } from "vitest";
import { revealScroll, revealSpan } from "./useRevealRow";

// a box 100 px high under a sticky head of 20 px, rows of 10 px: rows 0..7 in view at scroll 0
const box = (scroll: number) => ({ scroll, view: 100, head: 20, row: 10 });

describe("revealScroll", () => {
  it("leaves a row wholly in view alone", () => {
    expect(revealScroll(0, box(0))).toBeNull();
    expect(revealScroll(7, box(0))).toBeNull();
    expect(revealScroll(12, box(50))).toBeNull();
  });

  it("scrolls just enough to show a row below the view whole, at its bottom", () => {
    expect(revealScroll(8, box(0))).toBe(10);
    expect(revealScroll(59, box(0))).toBe(520);
  });

  it("scrolls a row above the view (or under the sticky head) to just under the head", () => {
    expect(revealScroll(4, box(50))).toBe(40);
    expect(revealScroll(0, box(5))).toBe(0);
  });

  it("does nothing where nothing is laid out or the row is not listed", () => {
    expect(revealScroll(30, { scroll: 0, view: 0, head: 0, row: 21 })).toBeNull();
    expect(revealScroll(-1, box(0))).toBeNull();
  });
});

describe("revealSpan", () => {
  // the same box: content px 20..100 in view at scroll 0, the head covering 0..20
  it("leaves a span wholly in view alone", () => {
    expect(revealSpan(20, 10, box(0))).toBeNull();
    expect(revealSpan(90, 10, box(0))).toBeNull();
  });

  it("scrolls a span below the view to the view's bottom, one above it (or under the head) to just under the head", () => {
    expect(revealSpan(1000, 24, box(0))).toBe(924);
    expect(revealSpan(60, 10, box(500))).toBe(40);
    expect(revealSpan(25, 10, box(10))).toBe(5);
  });

  it("never scrolls above the top", () => {
    expect(revealSpan(10, 10, box(30))).toBe(0);
  });
});
