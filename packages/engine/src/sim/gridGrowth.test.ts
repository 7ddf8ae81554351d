// The grid keeps up with a scene built one disc at a time inside a fixed region. Regression: the
// grid was rebuilt only when a disc landed outside it, so discs added at random spots inside the
// first ones' region filled cells sized for 64 bodies (10^5 additions took 24 s, each placement
// check scanning thousands of discs).
import { describe, expect, it } from "vitest";
import type { Grid } from "./grid.js";
import { World } from "./world.js";

/** Deterministic spots in [0, 1): a multiplicative congruential sequence (no Math.random). */
function spots(seed: number): () => number {
  let s = seed;
  return () => {
    s = (s * 48271) % 2147483647;
    return s / 2147483647;
  };
}

/** The most bodies any one grid cell holds. */
function crowdedCell(w: World): number {
  const g = (w as unknown as { grid: Grid }).grid;
  let most = 0;
  for (let c = 0; c < g.head.length; c++) {
    let k = 0;
    for (let s = g.head[c] as number; s >= 0; s = g.next[s] as number) k++;
    most = Math.max(most, k);
  }
  return most;
}

describe("a scene built inside a fixed region", () => {
  it("keeps the grid's cells small while the bodies multiply (they held hundreds)", () => {
    const n = 4000;
    const side = Math.sqrt((n * Math.PI) / 0.1); // 10 % packing at the end
    const w = new World({ g: 0 });
    // The region is fixed from the start: its four corners first.
    for (const [i, [x, y]] of [
      [1, 1],
      [side - 1, 1],
      [1, side - 1],
      [side - 1, side - 1],
    ].entries())
      w.addBody(`corner${i}`, { x: x as number, y: y as number, r: 1, m: 1 });
    const rnd = spots(7);
    let added = 4;
    for (let i = 0; added < n; i++) {
      try {
        w.addBody(`d${i}`, { x: 1 + rnd() * (side - 2), y: 1 + rnd() * (side - 2), r: 1, m: 1, vx: 1 });
        added++;
      } catch {
        // an overlap: try another spot
      }
    }
    expect(w.bodyCount).toBe(n);
    // Cells of about 3 per body hold 0.3 on average; a cell sized while there were 64 bodies held
    // about 200 of the 4,000.
    expect(crowdedCell(w)).toBeLessThanOrEqual(12);
  });
});
