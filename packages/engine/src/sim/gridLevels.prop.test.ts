// The grid's levels under fast-check: scenes of small discs with a few much larger ones, moving
// through the cells of every level, against walls, points and each other. The World whose grid has
// several levels must give the same events, bit for bit, as the World without a grid, also across
// edits that move a disc to another level. Each scene asserts that its grid has at least two
// occupied levels, so the property cannot pass on a one-level grid. Prints its seed; set FC_SEED to
// explore others.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { outcome } from "../../test/outcome.js";
import { lcg } from "../../test/randomScene.js";
import type { Grid } from "./grid.js";
import type { Optimizations } from "./types.js";
import { World } from "./world.js";

const SEED = Number(process.env.FC_SEED ?? 20261122);
const SIDE = 120;

interface Disc {
  id: string;
  x: number;
  y: number;
  r: number;
  vx: number;
  vy: number;
  m: number;
  mu: number;
}

/** 120-200 discs of radius 0.3-0.6 and 3-25 of radius 2-15, all moving, in a box of side 120. */
function levelScene(seed: number): { discs: Disc[]; g: number } {
  const rnd = lcg(seed);
  const friction = rnd() < 0.3;
  const small = 120 + Math.floor(rnd() * 80);
  const big = 3 + Math.floor(rnd() * 23);
  const discs: Disc[] = [];
  for (let k = 0; k < 20000 && discs.length < small + big; k++) {
    const isBig = discs.length < big;
    const r = isBig ? 2 + rnd() * 13 : 0.3 + rnd() * 0.3;
    const x = r + rnd() * (SIDE - 2 * r);
    const y = r + rnd() * (SIDE - 2 * r);
    if (discs.some((d) => Math.hypot(d.x - x, d.y - y) < d.r + r)) continue;
    const speed = isBig ? 8 : 20;
    discs.push({
      id: `d${String(discs.length).padStart(3, "0")}`,
      x,
      y,
      r,
      vx: (rnd() * 2 - 1) * speed,
      vy: (rnd() * 2 - 1) * speed,
      m: isBig && rnd() < 0.2 ? Number.POSITIVE_INFINITY : r * r,
      mu: friction ? rnd() * 0.5 : 0,
    });
  }
  return { discs, g: friction ? 1 : 0 };
}

function build(scene: ReturnType<typeof levelScene>, opt: Optimizations): World {
  const w = new World({ g: scene.g, optimizations: opt });
  w.addLine("s", [0, 0], [SIDE, 0], "segment");
  w.addLine("e", [SIDE, 0], [SIDE, SIDE], "segment");
  w.addLine("n", [SIDE, SIDE], [0, SIDE], "segment");
  w.addLine("w", [0, SIDE], [0, 0], "segment");
  w.addPoint("p", [SIDE / 2, -3]);
  for (const d of scene.discs) w.addBody(d.id, d);
  return w;
}

const gridOf = (w: World): Grid => (w as unknown as { grid: Grid }).grid;

/** Edits at the same instant in both worlds (each may be refused, in both alike, with the same message). */
function edit(w: World, seed: number): string[] {
  const rnd = lcg(seed ^ 0x2545f491);
  const ids = w.bodies().map((b) => b.id);
  const pick = () => ids[Math.floor(rnd() * ids.length)] as string;
  const tries: (() => void)[] = [
    () => w.updateBody(pick(), { r: 4 + rnd() * 8 }),
    () => w.updateBody(pick(), { r: 0.25 }),
    () => w.addBody("late", { x: rnd() * SIDE, y: rnd() * SIDE, r: 9, m: 81, vx: 6, vy: -4 }),
    () => w.updateBody(pick(), { x: 5 + rnd() * (SIDE - 10), y: 5 + rnd() * (SIDE - 10) }),
  ];
  return tries.map((t) => {
    try {
      t();
      return "ok";
    } catch (e) {
      return (e as Error).message;
    }
  });
}

describe("broad phase with levels", () => {
  it("the World with a grid of several levels matches the World without a grid, bit for bit", () => {
    console.log(`[grid levels] fast-check seed ${SEED} (set FC_SEED to change)`);
    let runs = 0;
    let multiLevel = 0;
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 2 ** 31 - 1 }), (seed) => {
        const scene = levelScene(seed);
        const grid = build(scene, {});
        const flat = build(scene, { broadPhase: false });
        expect(outcome(grid, 400)).toEqual(outcome(flat, 400));
        runs++;
        if (gridOf(grid).occupied.length >= 2) multiLevel++;
        expect(edit(grid, seed)).toEqual(edit(flat, seed));
        expect(outcome(grid, 400)).toEqual(outcome(flat, 400));
        expect(grid.bodies()).toEqual(flat.bodies());
      }),
      { seed: SEED, numRuns: 20, verbose: true },
    );
    // The property is about levels: most scenes must use several. Not every one: in about 3 % of
    // these scenes the cost model rightly takes one layout sized for the largest disc (FC_SEED=707
    // drew scene 329995747, 17 large discs among 121 small, when each scene had to have two levels).
    expect(multiLevel, `scenes with two or more occupied levels, of ${runs}`).toBeGreaterThanOrEqual(15);
  });

  // The grid took one layout for this scene when the property above first drew it.
  it("scene 329995747 (FC_SEED=707): the same result as without a grid", () => {
    const scene = levelScene(329995747);
    const grid = build(scene, {});
    const flat = build(scene, { broadPhase: false });
    expect(outcome(grid, 400)).toEqual(outcome(flat, 400));
    expect(edit(grid, 329995747)).toEqual(edit(flat, 329995747));
    expect(outcome(grid, 400)).toEqual(outcome(flat, 400));
    expect(grid.bodies()).toEqual(flat.bodies());
  });
});
