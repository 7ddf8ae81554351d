import { describe, expect, it } from "vitest";
import { revealScroll } from "./useRevealRow";

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
