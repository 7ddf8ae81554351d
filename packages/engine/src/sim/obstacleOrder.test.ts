// Building a scene of many obstacles: the World must give the same events, bit for bit, whatever
// order the segments, points and discs were added in, and whether the grid was rebuilt (every
// obstacle rasterized) after each add or once at the end. (Obstacles are kept in an indexed list,
// obstacleIndex.ts, so that a scene of m of them builds in O(m); ties between obstacles go by id.)
// Prints its seed; set FC_SEED to explore others.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { maze, mazeAdds, mazeWorld, obstacleOrder, shuffled } from "../../test/obstacleScene.js";
import { outcome } from "../../test/outcome.js";
import type { Grid } from "./grid.js";
import type { World } from "./world.js";

const SEED = Number(process.env.FC_SEED ?? 20261124);
const gridOf = (w: World): Grid => (w as unknown as { grid: Grid }).grid;

describe("a maze of many segments and pegs, added in any order", () => {
  it("gives the same events, bit for bit, and the same lists", () => {
    console.log(`[obstacle order] fast-check seed ${SEED} (set FC_SEED to change)`);
    let gridded = 0;
    let runs = 0;
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 2 ** 31 - 1 }), (seed) => {
        // 20 x 20 cells: 80 boundary walls and about 380 interior ones, 600 pegs, 8 discs.
        const m = maze(seed, 20, 600, 8);
        const adds = mazeAdds(m);
        const given = mazeWorld(adds);
        const orders = [
          [...adds].reverse(),
          shuffled(adds, seed ^ 0x5bd1e995),
          // discs first: each wall and peg is then checked against them as it comes
          [...adds.slice(-m.discs.length), ...shuffled(adds.slice(0, -m.discs.length), seed + 1)],
        ];
        const expected = outcome(given, 400);
        runs++;
        const g = gridOf(given);
        if (g.nx * g.ny > 1) gridded++;
        expect(expected.events.length).toBe(400);
        const kinds = new Set(expected.events.map((e) => e.kind));
        expect(kinds.has("bodyLine") && kinds.has("bodyPoint"), "walls and pegs are hit").toBe(true);
        for (const order of orders) {
          const w = mazeWorld(order);
          expect(outcome(w, 400)).toEqual(expected);
          expect(w.lines()).toEqual(given.lines());
          expect(w.points()).toEqual(given.points());
          expect(w.bodies()).toEqual(given.bodies());
        }
      }),
      { seed: SEED, numRuns: 8 },
    );
    // The grid is laid out over the obstacles (every run rasterizes them), not a single cell.
    expect(gridded, `runs on a grid of several cells, of ${runs}`).toBe(runs);
  });

  it("keeps the order of the lists the order of the adds", () => {
    const adds = shuffled(mazeAdds(maze(7, 12, 100, 3)), 11);
    const ids = (kind: string) => adds.filter((a) => a.kind === kind).map((a) => a.id);
    expect(obstacleOrder(mazeWorld(adds))).toEqual({ lines: ids("line"), points: ids("point") });
  });
});

describe("a maze built one add at a time equals the maze built at once", () => {
  it("with the World advanced after each add (each made locally or laying the grid out again), or a copy probed after each", () => {
    const m = maze(3, 8, 80, 5);
    const adds = mazeAdds(m);
    const atOnce = mazeWorld(adds);
    const expected = outcome(atOnce, 300);
    expect(expected.events.length).toBe(300);
    const kinds = new Set(expected.events.map((e) => e.kind));
    expect(kinds.has("bodyLine") && kinds.has("bodyPoint"), "walls and pegs are hit").toBe(true);
    // advance to the current time: the predictions are up to date before each next add, which
    // is then made in the grid as it is (obstacleUpkeep.ts), or lays it out again (their number doubled)
    const stepped = mazeWorld([]);
    // nextEventTime while edits are pending: a copy is probed, the World itself is left as it is
    const probed = mazeWorld([]);
    for (const a of adds) {
      a.add(stepped);
      stepped.advance({ untilTime: stepped.time });
      a.add(probed);
      probed.nextEventTime();
    }
    expect(outcome(stepped, 300)).toEqual(expected);
    expect(outcome(probed, 300)).toEqual(expected);
  });
});
