// The obstacle side of the grid's cost model (gridCost.ts: meanFreePath, eventCost, cheapestCell)
// and the layouts the World takes from it (broadPhase.ts): obstacles count when they are many, a
// scene of few obstacles keeps the layout sized by its bodies.
import { describe, expect, it } from "vitest";
import { GRID_CELL_MARGIN } from "../tolerances.js";
import type { Grid } from "./grid.js";
import { cheapestCell, eventCost, meanFreePath, type SceneLoad } from "./gridCost.js";
import { World } from "./world.js";

const INF = Number.POSITIVE_INFINITY;

/** n discs of radius r with `segments` segments of length `length` each and `points` points, in a side x side box. */
function load(n: number, segments: number, length: number, points: number, side: number, r = 1): SceneLoad {
  return {
    bodies: n,
    radii: new Array(n).fill(r),
    segments,
    segmentLength: segments * length,
    points,
    width: side,
    height: side,
  };
}

const gridOf = (w: World): Grid => (w as unknown as { grid: Grid }).grid;

/** 8 discs of radius 1 in a k x k lattice of cells 6 wide, walled by every lattice edge. */
function mazeWorld(k: number, discs = 8): World {
  const w = new World({ g: 0 });
  let id = 0;
  const seg = (x1: number, y1: number, x2: number, y2: number) =>
    w.addLine(`s${String(id++).padStart(5, "0")}`, [x1, y1], [x2, y2], "segment");
  for (let i = 0; i <= k; i++)
    for (let j = 0; j < k; j++) {
      seg(6 * i, 6 * j, 6 * i, 6 * j + 6);
      seg(6 * j, 6 * i, 6 * j + 6, 6 * i);
    }
  for (let i = 0; i < discs; i++)
    w.addBody(`d${i}`, { x: 6 * ((3 * i) % k) + 3, y: 6 * ((5 * i) % k) + 3, r: 1, m: 1, vx: 3, vy: 4 - i });
  w.advance({ maxEvents: 0 });
  return w;
}

describe("grid cost model with obstacles", () => {
  it("the mean free path of a gas is its area over 4 r (n - 1), and at most width + height", () => {
    expect(meanFreePath(load(101, 0, 0, 0, 100))).toBeCloseTo(10000 / 400, 12);
    // Segments of length l seen at a random angle: 2 l / π + 2 r each; points 2 r.
    const mixed = load(1, 10, 5, 20, 100, 0.5);
    expect(meanFreePath(mixed)).toBeCloseTo(10000 / ((2 * 50) / Math.PI + 10 + 20), 12);
    // A lone disc with nothing to hit leaves the box: its path counts as width + height.
    expect(meanFreePath(load(1, 0, 0, 0, 100))).toBe(200);
  });

  it("a single cell costs the tests of every body and obstacle; it wins with nothing to index", () => {
    const few = load(2, 0, 0, 0, 20);
    expect(eventCost(few, INF)).toBeLessThan(cheapestCell(few, 30, 30, 2 * GRID_CELL_MARGIN, 1e6).cost);
    // Each obstacle adds to the single cell's cost, not to the grid's.
    const many = load(8, 1000, 6, 0, 200);
    const grid = cheapestCell(many, 210, 210, 2 * GRID_CELL_MARGIN, 1e6);
    expect(eventCost(many, INF)).toBeGreaterThan(eventCost(load(8, 100, 6, 0, 200), INF) * 5);
    expect(grid.cost).toBeLessThan(0.1 * eventCost(many, INF));
    expect(grid.w).toBeLessThan(20);
  });

  it("cheapestCell starts at the side that keeps at most maxCells cells, and never returns less", () => {
    const l = load(8, 10000, 6, 0, 600);
    const capped = cheapestCell(l, 600, 600, 2, 100);
    expect(capped.w).toBeGreaterThanOrEqual(60);
    const free = cheapestCell(l, 600, 600, 2, 1e6);
    expect(free.w).toBeLessThan(capped.w);
    expect(free.cost).toBeLessThan(capped.cost);
  });

  it("in a maze, cells much smaller than the best pay crossings, much larger ones pay tests", () => {
    // Specks (r = 0.01), so that cells of any side above 0.02 fit them at level 0.
    const maze = load(8, 10000, 6, 0, 600, 0.01);
    const best = cheapestCell(maze, 600, 600, 0.02 * GRID_CELL_MARGIN, 1e9);
    // About the corridors' width: a cell holds a wall or two.
    expect(best.w).toBeGreaterThan(1);
    expect(best.w).toBeLessThan(12);
    expect(eventCost(maze, best.w / 4)).toBeGreaterThan(1.5 * best.cost);
    expect(eventCost(maze, best.w * 8)).toBeGreaterThan(1.5 * best.cost);
  });
});

describe("grid layouts the World takes", () => {
  it("Galperin's billiard (2 discs and a wall) keeps a single cell, also with a segment wall", () => {
    for (const kind of ["line", "segment"] as const) {
      const w = new World({ g: 0 });
      w.addLine("wall", [0, -1], [0, 1], kind);
      w.addBody("light", { x: 5, y: 0, r: 1, m: 1 });
      w.addBody("heavy", { x: 10, y: 0, r: 1, m: 1e6, vx: -1 });
      w.advance({ maxEvents: 3 });
      expect([gridOf(w).nx, gridOf(w).ny]).toEqual([1, 1]);
    }
  });

  it("8 discs among a few walls keep a single cell; in a maze of 400 segments they get cells near a disc's size", () => {
    const small = new World({ g: 0 });
    const corners: [number, number][] = [
      [0, 0],
      [40, 0],
      [40, 40],
      [0, 40],
    ];
    corners.forEach((p, i) => {
      small.addLine(`w${i}`, p, corners[(i + 1) % 4] as [number, number], "segment");
    });
    for (let i = 0; i < 8; i++) small.addBody(`d${i}`, { x: 4 + 4 * i, y: 20, r: 1, m: 1, vx: 1, vy: 1 });
    small.advance({ maxEvents: 0 });
    expect([gridOf(small).nx, gridOf(small).ny]).toEqual([1, 1]);
    const big = mazeWorld(10);
    const g = gridOf(big);
    expect(g.nx * g.ny).toBeGreaterThan(100);
    expect(g.w).toBeGreaterThanOrEqual(2 * GRID_CELL_MARGIN);
    expect(g.w).toBeLessThan(6);
    // The grid covers the maze (60 x 60), not only the discs.
    expect(g.ox).toBeLessThanOrEqual(0);
    expect(g.ox + g.nx * g.w).toBeGreaterThanOrEqual(60);
  });

  it("a gas of 400 discs in a box of 4 walls keeps the layout sized by its bodies", () => {
    const w = new World({ g: 0 });
    const side = Math.sqrt((400 * Math.PI) / 0.1);
    const walls: [number, number, number, number][] = [
      [0, 0, side, 0],
      [side, 0, side, side],
      [side, side, 0, side],
      [0, side, 0, 0],
    ];
    walls.forEach(([a, b, c, d], i) => {
      w.addLine(`w${i}`, [a, b], [c, d], "segment");
    });
    let minX = INF;
    for (let i = 0; i < 400; i++) {
      const x = ((i % 20) + 0.5) * (side / 20);
      minX = Math.min(minX, x);
      w.addBody(`b${String(i).padStart(3, "0")}`, {
        x,
        y: (Math.floor(i / 20) + 0.5) * (side / 20),
        r: 1,
        m: 1,
        vx: Math.cos(i),
        vy: Math.sin(i),
      });
    }
    w.advance({ maxEvents: 0 });
    const g = gridOf(w);
    // The body layout: 3 cells per body over the discs' box padded by two diameters (broadPhase.ts),
    // which starts right of the wall at x = 0 (a layout over the walls would start left of it).
    expect(g.ox).toBeCloseTo(minX - 4 * GRID_CELL_MARGIN, 9);
    expect(g.ox).toBeGreaterThan(-2);
    expect(g.nx * g.ny).toBeLessThan(3.1 * 400);
  });
});
