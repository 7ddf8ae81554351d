// The grid's obstacle rows (gridObstacles.ts) against a plain model, under fast-check: after any run
// of obstacles added and removed, the list renumbered after a removal, levels built as bodies enter
// them, and copies of the grid edited on either side, each built level's cell lists every code
// registered in a level-0 cell under it, once, its bit says whether it lists any, each level-0 cell's
// obstNear bit whether its 3 x 3 does, and a copy never sees the other's edits. Prints its seed; set FC_SEED to explore others.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { Grid } from "./grid.js";
import { addObstacle, removeObstacle, renumberAfterRemoval } from "./gridObstacleEdits.js";

const SEED = Number(process.env.FC_SEED ?? 20261124);
const NX = 13;
const NY = 9;

/** The model: each code's level-0 cells. */
type Model = Map<number, number[]>;

/**
 * What each cell of a built level of `g` should list, by the model. Compared in one assertion per
 * call (one per cell made the test spend most of its time in the assertions).
 */
function expectRows(g: Grid, model: Model): void {
  const got: [number, number[], number][] = [];
  const wanted: [number, number[], number][] = [];
  for (let k = 0; k < g.levels; k++) {
    if (!g.obstaclesBuilt(k)) continue;
    const want = new Map<number, number[]>();
    for (const [code, cells] of model) {
      const at = new Set(cells.map((c) => g.cellAt(k, c % NX, Math.floor(c / NX))));
      for (const cell of at) want.set(cell, [...(want.get(cell) ?? []), code]);
    }
    for (let cell = g.base[k] as number; cell < (g.base[k + 1] as number); cell++) {
      const row = [...g.obstList.subarray(g.obstStart[cell] as number, g.obstEnd[cell] as number)];
      const bit = ((g.obstBits[cell >> 5] as number) >>> (cell & 31)) & 1;
      const codes = (want.get(cell) ?? []).sort((a, b) => a - b);
      got.push([cell, row.sort((a, b) => a - b), bit]);
      wanted.push([cell, codes, codes.length > 0 ? 1 : 0]);
    }
  }
  // obstNear: a level-0 cell's bit says whether a cell of its 3 x 3 (clipped) lists anything
  const listed = new Set<number>();
  for (const cells of model.values()) for (const c of cells) listed.add(c);
  for (let cy = 0; cy < NY; cy++)
    for (let cx = 0; cx < NX; cx++) {
      let want = 0;
      for (let y = Math.max(0, cy - 1); y <= Math.min(NY - 1, cy + 1); y++)
        for (let x = Math.max(0, cx - 1); x <= Math.min(NX - 1, cx + 1); x++)
          if (listed.has(y * NX + x)) want = 1;
      const c = cy * NX + cx;
      got.push([-1 - c, [], ((g.obstNear[c >> 5] as number) >>> (c & 31)) & 1]);
      wanted.push([-1 - c, [], want]);
    }
  expect(got).toEqual(wanted);
}

const cellsArb = fc.uniqueArray(fc.integer({ min: 0, max: NX * NY - 1 }), { minLength: 1, maxLength: 12 });
const opArb = fc.oneof(
  fc.record({ op: fc.constant("add" as const), cells: cellsArb }),
  fc.record({ op: fc.constant("remove" as const), pick: fc.nat() }),
  fc.record({ op: fc.constant("drop" as const), pick: fc.nat() }),
  fc.record({ op: fc.constant("enter" as const), level: fc.nat(4) }),
  fc.record({ op: fc.constant("copy" as const) }),
);

describe("grid obstacle rows", () => {
  it("list what a plain model lists, through adds, removals, renumbering, new levels and copies", () => {
    console.log(`[grid obstacles] fast-check seed ${SEED} (set FC_SEED to change)`);
    fc.assert(
      fc.property(
        fc.array(cellsArb, { maxLength: 20 }),
        fc.array(opArb, { minLength: 20, maxLength: 120 }),
        (initial, ops) => {
          let g = new Grid(16);
          g.reset(0, 0, 1, NX, NY);
          // Lines 0.. and points -1, -2, ... alternately; a body in level 1 before the rows are set.
          g.enter(0, 1, g.cellAt(1, 0, 0));
          let model: Model = new Map();
          let lines = 0;
          let points = 0;
          const pairs: number[] = [];
          initial.forEach((cells, i) => {
            const code = i % 2 === 0 ? lines++ : -++points;
            model.set(code, cells);
            for (const c of cells) pairs.push(c, code);
          });
          g.setObstacles(pairs);
          let slot = 1;
          let copies = 0;
          /** The grid left as it was when copied (the edits go on in the other). */
          let frozen: { grid: Grid; model: Model } | null = null;
          for (const o of ops) {
            if (o.op === "add") {
              const code = model.size % 2 === 0 ? lines++ : -++points;
              addObstacle(g, code, o.cells);
              model.set(code, o.cells);
            } else if (o.op === "enter") {
              const k = Math.min(o.level, g.levels - 1);
              if (slot < 16) g.enter(slot++, k, g.cellAt(k, 5, 5));
            } else if (o.op === "copy") {
              // Edit the copy, or go on with the original, in turn.
              const copy = g.clone();
              if (copies++ % 2 === 0) {
                frozen = { grid: g, model: new Map(model) };
                g = copy;
              } else frozen = { grid: copy, model: new Map(model) };
            } else if (model.size > 0) {
              const codes = [...model.keys()];
              const code = codes[o.pick % codes.length] as number;
              removeObstacle(g, code, model.get(code) as number[]);
              model.delete(code);
              if (o.op === "drop") {
                // The list closed the gap: the codes after it move down by one.
                const renumbered: Model = new Map();
                for (const [c, cells] of model) {
                  if (code >= 0) renumbered.set(c > code ? c - 1 : c, cells);
                  else renumbered.set(c < code ? c + 1 : c, cells);
                }
                if (code >= 0) {
                  renumberAfterRemoval(g, code);
                  lines--;
                } else {
                  renumberAfterRemoval(g, undefined, -code - 1);
                  points--;
                }
                model = renumbered;
              }
            }
            expectRows(g, model);
            if (frozen !== null) expectRows(frozen.grid, frozen.model);
          }
        },
      ),
      { seed: SEED, numRuns: 100 },
    );
  });

  it("keep no arrays of row ends and rooms of their own until an obstacle is edited in place", () => {
    // Packed rows read their ends from obstStart; a copy edited in place gets its own, the original keeps none.
    const ownsEnds = (g: Grid) =>
      g.obstEnd.buffer !== g.obstStart.buffer || g.obstCap.buffer !== g.obstStart.buffer;
    const g = new Grid(4);
    g.reset(0, 0, 1, NX, NY);
    g.enter(0, 0, g.cellAt(0, 2, 2));
    g.setObstacles([0, 0, 1, 0, 14, -1]);
    expect(ownsEnds(g)).toBe(false);
    g.enter(1, 2, g.cellAt(2, 4, 4));
    renumberAfterRemoval(g, undefined, 0);
    expect(ownsEnds(g)).toBe(false);
    const copy = g.clone();
    addObstacle(copy, 1, [5, 6]);
    expect(ownsEnds(copy)).toBe(true);
    expect(ownsEnds(g)).toBe(false);
    removeObstacle(g, 0, [0, 1]);
    expect(ownsEnds(g)).toBe(true);
    expect([...g.obstList.subarray(g.obstStart[14] as number, g.obstEnd[14] as number)]).toEqual([-1]);
    expect([...copy.obstList.subarray(copy.obstStart[5] as number, copy.obstEnd[5] as number)]).toEqual([1]);
  });
});
