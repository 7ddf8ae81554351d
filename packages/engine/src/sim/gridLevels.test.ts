// The grid's levels (grid.ts): nested cells, the level that fits each radius, and when levels pay
// (gridCost.ts).
import { describe, expect, it } from "vitest";
import { lcg } from "../../test/randomScene.js";
import { GRID_CELL_MARGIN } from "../tolerances.js";
import { Grid } from "./grid.js";
import { levelOfRadius, levelsPay, predictionCost, singleCellLevel } from "./gridCost.js";
import { World } from "./world.js";

describe("Grid levels", () => {
  it("has levels of cells twice as wide up to a single cell, which fits any radius", () => {
    const g = new Grid(8);
    g.reset(-10, -20, 2, 100, 40);
    // Level k fits r <= 2 * 2^k / (2 * margin): 1, 2, 4, ..., and the single cell anything.
    expect(g.levels).toBe(8);
    expect([...g.nxOf]).toEqual([100, 50, 25, 13, 7, 4, 2, 1]);
    expect([...g.nyOf]).toEqual([40, 20, 10, 5, 3, 2, 1, 1]);
    expect([...g.base]).toEqual([0, 4000, 5000, 5250, 5315, 5336, 5344, 5346, 5347]);
    expect(g.levelFor(0.5)).toBe(0);
    expect(g.levelFor(1.5)).toBe(1);
    expect(g.levelFor(7)).toBe(3);
    expect(g.fitR[6]).toBeCloseTo(64 / GRID_CELL_MARGIN, 12);
    expect(g.fitR[7]).toBe(Number.POSITIVE_INFINITY);
    expect(g.levelFor(1e9)).toBe(7);
  });

  it("one cell for everything when nx = ny = 1", () => {
    const g = new Grid(8);
    g.reset(0, 0, 1, 1, 1);
    expect(g.levels).toBe(1);
    expect(g.levelFor(1e9)).toBe(0);
  });

  it("level 0 fits the radius its side was computed from, whatever the rounding", () => {
    const g = new Grid(8);
    const r = 0.1;
    g.reset(0, 0, 2 * r * GRID_CELL_MARGIN, 50, 50, r);
    expect(g.levelFor(r)).toBe(0);
  });

  it("a coarse cell lists the obstacle codes of the level-0 cells under it, once each, from when a body first enters its level", () => {
    const g = new Grid(8);
    g.reset(0, 0, 1, 37, 23);
    const rnd = lcg(11);
    const level0: number[] = [];
    // Codes -5..29 (points and segments), each in a run of neighbouring cells, as a raster gives.
    for (let code = -5; code < 30; code++) {
      let cx = Math.floor(rnd() * 37);
      let cy = Math.floor(rnd() * 23);
      const cells = new Set<number>();
      for (let i = 0, n = code < 0 ? 1 : 1 + Math.floor(rnd() * 40); i < n; i++) {
        if (!cells.has(cy * 37 + cx)) level0.push(cy * 37 + cx, code);
        cells.add(cy * 37 + cx);
        cx = Math.min(36, Math.max(0, cx + Math.floor(rnd() * 3) - 1));
        cy = Math.min(22, Math.max(0, cy + Math.floor(rnd() * 3) - 1));
      }
    }
    // Level 2 holds a body before the obstacles are set; the others get theirs when a body enters.
    g.enter(0, 2, g.cellAt(2, 5, 5));
    g.setObstacles(level0);
    expect(g.levels).toBeGreaterThan(4);
    const built = (k: number) => g.obstaclesBuilt(k);
    expect([...Array(g.levels).keys()].filter(built)).toEqual([0, 2]);
    for (let k = 1; k < g.levels; k++) {
      if (k !== 2) g.enter(k, k, g.cellAt(k, 0, 0));
      expect(built(k)).toBe(true);
    }
    for (let k = 0; k < g.levels; k++) {
      // Expected: each (level-k cell, code) over level 0's pairs, once.
      const want = new Map<number, number[]>();
      for (let i = 0; i < level0.length; i += 2) {
        const c = level0[i] as number;
        const cell = g.cellAt(k, c % 37, Math.floor(c / 37));
        const list = want.get(cell) ?? [];
        if (!list.includes(level0[i + 1] as number)) list.push(level0[i + 1] as number);
        want.set(cell, list);
      }
      for (let cell = g.base[k] as number; cell < (g.base[k + 1] as number); cell++) {
        // (the order within a cell is no contract: ties between obstacles go by id)
        const got = [...g.obstList.subarray(g.obstStart[cell] as number, g.obstEnd[cell] as number)];
        expect(got.sort((x, y) => x - y)).toEqual((want.get(cell) ?? []).sort((x, y) => x - y));
      }
    }
    // obstNear: a level-0 cell's bit is set exactly when a cell of its 3 x 3 (clipped) lists something.
    const lists = (c: number) => (g.obstEnd[c] as number) > (g.obstStart[c] as number);
    let near = 0;
    for (let cy = 0; cy < 23; cy++)
      for (let cx = 0; cx < 37; cx++) {
        let want = false;
        for (let y = Math.max(0, cy - 1); y <= Math.min(22, cy + 1); y++)
          for (let x = Math.max(0, cx - 1); x <= Math.min(36, cx + 1); x++) want ||= lists(y * 37 + x);
        const c = cy * 37 + cx;
        const got = ((g.obstNear[c >> 5] as number) & (1 << (c & 31))) !== 0;
        expect(got).toBe(want);
        if (got) near++;
      }
    expect(near).toBeGreaterThan(0);
    expect(near).toBeLessThan(37 * 23);
  });

  it("a point's cell at level k holds its level-0 cell, and level k's boundaries are level 0's", () => {
    const g = new Grid(8);
    g.reset(-3, 5, 1.5, 37, 23);
    const rnd = lcg(7);
    for (let i = 0; i < 500; i++) {
      const x = -10 + rnd() * 70;
      const y = 0 + rnd() * 45;
      const cx = g.column(x);
      const cy = g.row(y);
      for (let k = 0; k < g.levels; k++) {
        const cell = g.cellAt(k, cx, cy) - (g.base[k] as number);
        const kx = cell % (g.nxOf[k] as number);
        const ky = (cell - kx) / (g.nxOf[k] as number);
        // Inside the level-k cell's bounds, computed as level 0's boundaries (edges unbounded).
        const last = (g.nxOf[k] as number) - 1;
        if (kx > 0) expect(x).toBeGreaterThanOrEqual(g.boundaryX(kx << k));
        if (kx < last) expect(x).toBeLessThan(g.boundaryX((kx + 1) << k));
        if (ky > 0) expect(y).toBeGreaterThanOrEqual(g.boundaryY(ky << k));
        if (ky < (g.nyOf[k] as number) - 1) expect(y).toBeLessThan(g.boundaryY((ky + 1) << k));
      }
    }
  });

  it("counts the bodies of each level and lists the levels that hold any", () => {
    const g = new Grid(8);
    g.reset(0, 0, 1, 16, 16);
    g.enter(0, 0, g.cellAt(0, 1, 1));
    g.enter(1, 2, g.cellAt(2, 9, 9));
    g.enter(2, 2, g.cellAt(2, 9, 10));
    expect(g.occupied).toEqual([0, 2]);
    expect([...g.count]).toEqual([1, 0, 2, 0, 0]);
    expect(g.flat).toBe(false);
    g.leave(1);
    g.leave(1);
    expect([...g.count]).toEqual([1, 0, 1, 0, 0]);
    g.leave(0);
    expect(g.occupied).toEqual([2]);
    g.enter(0, 0, g.cellAt(0, 1, 1));
    g.leave(2);
    expect(g.flat).toBe(true);
    g.leave(0);
    g.enter(2, 2, g.cellAt(2, 9, 10));
    const c = g.clone();
    c.leave(2);
    expect(c.occupied).toEqual([]);
    expect(g.occupied).toEqual([2]);
  });
});

describe("when levels pay", () => {
  const gasArea = (radii: number[]) => radii.reduce((a, r) => a + Math.PI * r * r, 0) / 0.1;

  it("levels: a hundred discs of radius 20 among 10,000 of radius 1", () => {
    const radii = [...Array.from({ length: 100 }, () => 20), ...Array.from({ length: 10000 }, () => 1)];
    const area = gasArea(radii);
    const w0 = Math.sqrt(area / 30000);
    expect(levelOfRadius(20, w0)).toBe(3);
    expect(levelsPay(radii, area, w0, 40)).toBe(true);
  });

  it("one level: radii spread evenly on a log scale from 1 to 30 (cells sized for the density fit most)", () => {
    const rnd = lcg(5);
    const radii = Array.from({ length: 10000 }, () => Math.exp(rnd() * Math.log(30)));
    const area = gasArea(radii);
    const w0 = Math.sqrt(area / 30000);
    expect(levelsPay(radii, area, w0, 60)).toBe(false);
    expect(predictionCost(radii, area, w0, 60, true)).toBeLessThan(
      predictionCost(radii, area, w0, 60, false),
    );
  });

  it("one level when one size fits all", () => {
    const radii = Array.from({ length: 1000 }, () => 1);
    expect(levelsPay(radii, gasArea(radii), 2, 2)).toBe(false);
  });

  it("no levels for a line of specks with discs among them (the discs would all land in the single top cell)", () => {
    // Level-0 cells sized for the specks in a flat region are so small that a disc of radius 1
    // would fit only the single top cell, tested against every body; the estimate counts that
    // level as such (gridCost.ts, `top`), not as a level of cells that fit the discs.
    const w = new World({ g: 0 });
    for (let i = 0; i < 1000; i++)
      w.addBody(`s${String(i).padStart(4, "0")}`, { x: 3 * i, y: 0, r: 1e-6, m: 1, vx: i % 2 ? 1 : -1 });
    for (let i = 0; i < 50; i++)
      w.addBody(`d${String(i).padStart(2, "0")}`, { x: 60 * i + 1.5, y: 0, r: 1, m: 1 });
    w.advance({ maxEvents: 10 });
    const grid = (w as unknown as { grid: Grid }).grid;
    expect(grid.levelFor(1)).toBeLessThan(grid.levels - 1);
  });

  it("the single-cell level of a grid", () => {
    expect(singleCellLevel(1, 1)).toBe(0);
    expect(singleCellLevel(2, 1)).toBe(1);
    expect(singleCellLevel(100, 40)).toBe(7);
  });
});
