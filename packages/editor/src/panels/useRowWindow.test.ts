import { describe, expect, it } from "vitest";
import { OVERSCAN, type RowRun, rowRuns, rowWindow } from "./useRowWindow";

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

describe("rowRuns", () => {
  const win = rowWindow(60, 420, 200, 20, 20); // rows 16..34 rendered
  const total = (runs: RowRun[]) => runs.reduce((px, r) => px + ("gap" in r ? r.gap : 20), 0);

  it("without held rows: the window between two spacers", () => {
    const runs = rowRuns(win, [], 60, 20);
    expect(runs[0]).toEqual({ gap: win.before, from: 0 });
    expect(runs.at(-1)).toEqual({ gap: win.after, from: win.end });
    expect(runs.filter((r) => "row" in r).map((r) => (r as { row: number }).row)).toEqual(
      Array.from({ length: win.end - win.start }, (_, k) => win.start + k),
    );
    expect(total(runs)).toBe(60 * 20);
  });

  it("a held row out of the window is rendered at its own place, the spacers around it one row shorter", () => {
    const runs = rowRuns(win, [2, 50, 20, 99], 60, 20);
    expect(runs.slice(0, 4)).toEqual([
      { gap: 40, from: 0 },
      { row: 2 },
      { gap: (win.start - 3) * 20, from: 3 },
      { row: win.start },
    ]);
    expect(runs.slice(-3)).toEqual([
      { gap: (50 - win.end) * 20, from: win.end },
      { row: 50 },
      { gap: 9 * 20, from: 51 },
    ]);
    // a held row inside the window is rendered once; an index past the rows is not one
    expect(runs.filter((r) => "row" in r && r.row === 20)).toHaveLength(1);
    expect(runs.some((r) => "row" in r && r.row === 99)).toBe(false);
    expect(total(runs)).toBe(60 * 20);
  });

  it("held rows at the ends leave no empty spacer", () => {
    const runs = rowRuns(win, [0, 59], 60, 20);
    expect(runs[0]).toEqual({ row: 0 });
    expect(runs.at(-1)).toEqual({ row: 59 });
    expect(total(runs)).toBe(60 * 20);
  });
});
