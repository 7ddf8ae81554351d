import { describe, expect, it } from "vitest";
import { OVERSCAN, rowWindow } from "./useRowWindow";

describe("rowWindow", () => {
  it("renders the rows in view plus OVERSCAN each side, spacers standing for the rest", () => {
    // 60 rows of 20 px under a 20 px header, a 200 px view scrolled to 420 px: rows 20..29 in view.
    const w = rowWindow(60, 420, 200, 20, 20);
    expect(w).toEqual({
      start: 20 - OVERSCAN,
      end: 31 + OVERSCAN,
      before: (20 - OVERSCAN) * 20,
      after: (60 - 31 - OVERSCAN) * 20,
    });
    expect(w.before + (w.end - w.start) * 20 + w.after).toBe(60 * 20);
  });

  it("at the top and the bottom the window is cut to the rows that exist", () => {
    expect(rowWindow(60, 0, 200, 20, 20)).toMatchObject({ start: 0, before: 0 });
    const bottom = rowWindow(60, 60 * 20 + 20 - 200, 200, 20, 20);
    expect(bottom).toMatchObject({ end: 60, after: 0 });
  });

  it("without a laid-out view every row is rendered", () => {
    expect(rowWindow(60, 0, 0, 0, 20)).toEqual({ start: 0, end: 60, before: 0, after: 0 });
    expect(rowWindow(0, 100, 200, 20, 20)).toEqual({ start: 0, end: 0, before: 0, after: 0 });
  });
});
