// When an obstacle edit keeps the grid's layout and predicts again only the bodies it concerns
// (obstacleUpkeep.ts), and when it leaves the predictions out of date for a full rebuild: infinite
// lines and rays added or moved, the segments and points grown past what the layout was chosen for
// and the cost estimate now choosing another. (That the local path gives the full rebuild's events
// bit for bit: obstacleUpkeep.prop.test.ts.)
import { describe, expect, it } from "vitest";
import { maze, mazeAdds, mazeWorld } from "../../test/obstacleScene.js";
import type { Grid } from "./grid.js";
import { World } from "./world.js";

interface Internals {
  grid: Grid;
  dirty: boolean;
  gridForObstacles: boolean;
}
const inside = (w: World): Internals => w as unknown as Internals;

/** 400 discs on a 20 x 20 lattice, moving. */
function crowd(): World {
  const w = new World({ g: 0 });
  for (let i = 0; i < 400; i++) {
    const a = (i * 2.399963) % (2 * Math.PI);
    w.addBody(`d${String(i).padStart(3, "0")}`, {
      x: (i % 20) * 4,
      y: Math.floor(i / 20) * 4,
      r: 1,
      m: 1,
      vx: Math.cos(a),
      vy: Math.sin(a),
    });
  }
  w.advance({ maxEvents: 10 });
  return w;
}

describe("obstacle edits among many discs", () => {
  it("keep the layout: walls and pegs added, moved and removed one at a time leave the predictions up to date", () => {
    const w = crowd();
    const layout = () => {
      const g = inside(w).grid;
      return { ox: g.ox, oy: g.oy, w: g.w, nx: g.nx, ny: g.ny };
    };
    const before = layout();
    expect(before.nx * before.ny).toBeGreaterThan(1);
    let full = 0;
    const edit = (f: () => void) => {
      f();
      if (inside(w).dirty) full++;
      w.advance({ maxEvents: 1 });
    };
    // 300 short walls on a ring around the discs, 150 pegs between them: well past twice
    // GRID_MIN_BODIES, so the cost estimate is asked again (and keeps the body layout).
    for (let i = 0; i < 300; i++) {
      const a = (i / 300) * 2 * Math.PI;
      const b = ((i + 1) / 300) * 2 * Math.PI;
      edit(() =>
        w.addLine(
          `s${i}`,
          [38 + 100 * Math.cos(a), 38 + 100 * Math.sin(a)],
          [38 + 100 * Math.cos(b), 38 + 100 * Math.sin(b)],
          "segment",
        ),
      );
    }
    for (let i = 0; i < 150; i++)
      edit(() => w.addPoint(`p${i}`, [38 + 90 * Math.cos(i), 38 + 90 * Math.sin(i)]));
    // every third wall's first end moved out
    for (let i = 0; i < 300; i += 3) {
      const a = (i / 300) * 2 * Math.PI;
      edit(() => w.updateLine(`s${i}`, { p1: [38 + 105 * Math.cos(a), 38 + 105 * Math.sin(a)] }));
    }
    for (let i = 0; i < 150; i += 2) edit(() => w.removePoint(`p${i}`));
    for (let i = 0; i < 300; i += 2) edit(() => w.removeLine(`s${i}`));
    expect(full).toBe(0);
    expect(layout()).toEqual(before);
    expect(w.lines().length).toBe(150);
    expect(w.points().length).toBe(75);
  });

  it("lay the grid out again for an infinite line or ray added or moved", () => {
    const w = crowd();
    w.addLine("ray", [-10, -10], [-10, 0], "ray");
    expect(inside(w).dirty).toBe(true);
    w.advance({ maxEvents: 3 });
    w.updateLine("ray", { p1: [-11, -10] });
    expect(inside(w).dirty).toBe(true);
    w.advance({ maxEvents: 3 });
    // a ray turned into a segment, and removed: local
    w.updateLine("ray", { kind: "segment" });
    expect(inside(w).dirty).toBe(false);
    w.removeLine("ray");
    expect(inside(w).dirty).toBe(false);
  });
});

describe("obstacle edits among a few discs", () => {
  it("lay the grid out for the obstacles once they pay for it, as a World built at once does", () => {
    // 8 discs: a single cell while the walls are few; a maze of 12 x 12 cells of walls and 200
    // pegs added one per advance ends on the obstacle layout, as the maze built at once.
    const m = maze(5, 12, 200, 8);
    const adds = mazeAdds(m);
    const discs = adds.slice(-m.discs.length);
    const obstacles = adds.slice(0, -m.discs.length);
    const w = mazeWorld(discs);
    w.advance({ maxEvents: 0 });
    expect(inside(w).grid.nx * inside(w).grid.ny).toBe(1);
    let full = 0;
    let local = 0;
    for (const a of obstacles) {
      a.add(w);
      if (inside(w).dirty) full++;
      else local++;
      w.advance({ untilTime: w.time });
    }
    const atOnce = mazeWorld(adds);
    atOnce.advance({ maxEvents: 0 });
    expect(inside(atOnce).gridForObstacles).toBe(true);
    expect(inside(w).gridForObstacles).toBe(true);
    const ratio = inside(w).grid.w / inside(atOnce).grid.w;
    expect(ratio).toBeGreaterThanOrEqual(0.5);
    expect(ratio).toBeLessThanOrEqual(2);
    // Laid out again O(log m) times, not after every add.
    expect(full).toBeGreaterThan(0);
    expect(full).toBeLessThanOrEqual(Math.ceil(Math.log2(obstacles.length)));
    expect(local).toBe(obstacles.length - full);
  });
});
