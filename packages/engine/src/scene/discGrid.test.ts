// DiscGrid's overlap query, and the review's hang: far from the origin (cell numbers beyond 2^53)
// the cell loop never advanced, so a scene with a disc at (4e16, 4e16) froze Timeline.fromScene.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { Timeline } from "../timeline/timeline.js";
import { DiscGrid } from "./discGrid.js";
import { discsOverlap } from "./overlap.js";

describe("DiscGrid", () => {
  it("finds the smallest overlapping id, skips `except`, and nothing for a disc that only touches", () => {
    const g = new DiscGrid();
    g.insert("b", 0, 0, 1);
    g.insert("a", 1.5, 0, 1);
    g.insert("c", 10, 0, 1);
    expect(g.findOverlap(0.5, 0, 1, null)).toBe("a");
    expect(g.findOverlap(0.5, 0, 1, "a")).toBe("b");
    expect(g.findOverlap(12, 0, 1, null)).toBeNull();
  });

  it("answers far from the origin (cell numbers beyond 2^53) instead of looping", () => {
    for (const far of [4e16, 1e17, -1e17, 1e30]) {
      const g = new DiscGrid();
      g.insert("a", 0, 0, 1);
      g.insert("b", far, far, 1);
      expect(g.findOverlap(far, far + 1, 1, null)).toBe("b");
      expect(g.findOverlap(far, -far, 1, null)).toBeNull();
    }
  });

  it("a scene with a disc at (4e16, 4e16) loads (Timeline.fromScene returned only at 1e16 and below)", () => {
    const tl = Timeline.fromScene({
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, 0],
      actions: [
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
        { time: 0, type: "addBody", id: "b", x: 4e16, y: 4e16, r: 1, m: 1 },
      ],
    });
    expect(tl.stateAt(0).bodies.map((b) => b.id)).toEqual(["a", "b"]);
  });

  it("answers as a scan of every disc would, through inserts, moves, removals and clears", () => {
    // coordinates on a coarse lattice (so discs often overlap or touch), some far from the origin
    const coord = fc.oneof(
      fc.integer({ min: -40, max: 40 }).map((k) => k / 4),
      fc.constantFrom(3e9, -3e9, 4e16, 1e30),
    );
    const radius = fc.constantFrom(0.25, 0.5, 1, 3);
    // enough discs that a query looks in its cells, not at every disc
    const id = fc.integer({ min: 0, max: 59 }).map((k) => `d${k}`);
    const step = fc.oneof(
      {
        arbitrary: fc.record({ op: fc.constant("insert" as const), id, x: coord, y: coord, r: radius }),
        weight: 8,
      },
      { arbitrary: fc.record({ op: fc.constant("remove" as const), id }), weight: 2 },
      { arbitrary: fc.record({ op: fc.constant("clear" as const) }), weight: 1 },
      {
        arbitrary: fc.record({
          op: fc.constant("query" as const),
          x: coord,
          y: coord,
          r: radius,
          except: fc.option(id),
        }),
        weight: 8,
      },
    );
    fc.assert(
      fc.property(fc.array(step, { maxLength: 200 }), (steps) => {
        const grid = new DiscGrid();
        const discs = new Map<string, { x: number; y: number; r: number }>();
        for (const s of steps) {
          if (s.op === "insert") {
            if (discs.has(s.id)) grid.insert(s.id, s.x, s.y, s.r);
            else grid.add(s.id, s.x, s.y, s.r);
            discs.set(s.id, { x: s.x, y: s.y, r: s.r });
          } else if (s.op === "remove") {
            grid.remove(s.id);
            discs.delete(s.id);
          } else if (s.op === "clear") {
            grid.clear();
            discs.clear();
          } else {
            const hits = [...discs]
              .filter(([k, d]) => k !== s.except && discsOverlap(s.x, s.y, s.r, d.x, d.y, d.r))
              .map(([k]) => k)
              .sort();
            expect(grid.findOverlap(s.x, s.y, s.r, s.except)).toBe(hits[0] ?? null);
          }
          expect(grid.size).toBe(discs.size);
        }
      }),
      { seed: seedFor("DiscGrid against a scan"), numRuns: 300 },
    );
  });
});
