/**
 * The benchmark's obstacle-heavy scenes (bench/scenes/obstacles.mjs) and their rows in the report
 * (bench/report/obstacles.mjs): a maze has the segments asked for, its discs clear of every wall and
 * of each other; a Galton board has its pegs inside the box and its balls above them; the same seed
 * gives the same scene; the report gives each row's cost against the row of fewest obstacles of its
 * kind and the time to build it (a dash for a run from before builds were timed), keeps an error
 * row, and writes nothing for a run from before the rows existed.
 */
import { describe, expect, it } from "vitest";
import { obstaclesBlock } from "../../bench/report/obstacles.mjs";
import { galton, maze } from "../../bench/scenes/obstacles.mjs";

/** Distance from (px, py) to the segment (a, b). */
function toSegment(px: number, py: number, a: number[], b: number[]): number {
  const [ax, ay] = a as [number, number];
  const [bx, by] = b as [number, number];
  const t = Math.max(
    0,
    Math.min(1, ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2)),
  );
  return Math.hypot(px - (ax + t * (bx - ax)), py - (ay + t * (by - ay)));
}

describe("obstacle-heavy scenes", () => {
  for (const [discs, segments] of [
    [8, 100],
    [40, 1000],
  ] as const) {
    it(`a maze of ${segments} segments with ${discs} discs clear of the walls and of each other`, () => {
      const scene = maze({ discs, segments });
      expect(scene.walls).toHaveLength(segments);
      expect(scene.bodies).toHaveLength(discs);
      expect(new Set(scene.walls.map((w) => w.id)).size).toBe(segments);
      for (const b of scene.bodies) {
        for (const w of scene.walls) expect(toSegment(b.x, b.y, w.p1, w.p2)).toBeGreaterThan(b.r);
        for (const o of scene.bodies)
          if (o !== b) expect(Math.hypot(o.x - b.x, o.y - b.y)).toBeGreaterThan(2);
      }
      expect(maze({ discs, segments })).toEqual(scene);
    });
  }

  it("a Galton board of 1,000 pegs inside its box, the balls above the pegs and apart", () => {
    const scene = galton({ balls: 5, pegs: 1000 });
    const { x0, y0, x1, y1 } = scene.box as { x0: number; y0: number; x1: number; y1: number };
    expect(scene.points).toHaveLength(1000);
    const top = Math.max(...scene.points.map((p) => p.p[1] as number));
    for (const p of scene.points) {
      const [x, y] = p.p as [number, number];
      // Room for a ball (diameter 2) between a peg and a wall.
      expect(x - x0).toBeGreaterThan(2);
      expect(x1 - x).toBeGreaterThan(2);
      expect(y - y0).toBeGreaterThan(2);
      expect(y1 - y).toBeGreaterThan(2);
    }
    scene.bodies.forEach((b, i) => {
      expect(b.y - b.r).toBeGreaterThan(top + 1);
      expect(b.y + b.r).toBeLessThan(y1);
      for (const o of scene.bodies.slice(i + 1))
        expect(Math.hypot(o.x - b.x, o.y - b.y)).toBeGreaterThan(b.r + o.r);
    });
    expect(galton({ balls: 5, pegs: 1000 })).toEqual(scene);
  });
});

const row = (kind: string, obstacles: number, usPerEvent: number, sameAsOff = true) => ({
  kind,
  discs: 8,
  obstacles,
  batch: 50000,
  runs: 3,
  usPerEvent,
  cells: 676,
  offUsPerEvent: 100,
  sameAsOff,
  buildMs: obstacles / 400,
  buildUsPerObstacle: 2.5,
});

describe("obstacle-heavy scenes in the report", () => {
  it("gives each row's cost against the row of fewest obstacles of its kind, and keeps an error row", () => {
    const out: string[] = [];
    obstaclesBlock(
      {
        obstacles: {
          rows: [
            row("maze", 100, 2),
            row("maze", 10000, 3, false),
            row("galton", 1000, 5),
            row("galton", 5000, 7.5),
            { kind: "galton", discs: 5, obstacles: 9000, error: "boom" },
            // a row from a run before builds were timed
            (({ buildMs, buildUsPerObstacle, ...before }) => before)(row("maze", 400, 2)),
          ],
        },
      },
      out,
    );
    const text = out.join("\n");
    expect(text).toContain("| maze | 8 | 100 | 676 | 50,000 | 3 | 2 | 1× | 100 | yes | 0.25 | 2.5 |");
    expect(text).toContain("| maze | 8 | 10,000 | 676 | 50,000 | 3 | 3 | 1.5× | 100 | **no** | 25 | 2.5 |");
    expect(text).toContain("| galton | 8 | 5,000 | 676 | 50,000 | 3 | 7.5 | 1.5× | 100 | yes | 12.5 | 2.5 |");
    expect(text).toContain("| galton | 5 | 9,000 |  |  |  | error: boom |  |  |  |  |  |");
    expect(text).toContain("| maze | 8 | 400 | 676 | 50,000 | 3 | 2 | 1× | 100 | yes | — | — |");
  });

  it("writes nothing for a run from before the rows existed", () => {
    const out: string[] = [];
    obstaclesBlock({}, out);
    expect(out).toEqual([]);
  });
});
