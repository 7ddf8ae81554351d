import { describe, expect, it } from "vitest";
import type { LineKind } from "./obstacles.js";
import { World } from "./world.js";

/**
 * Discs r = 1 in parallel channels exactly their diameter wide (walls shared, 2e6 long), falling
 * under gravity or sliding with friction: each disc touches both walls all the way without being
 * pushed, and every wall's end points lie on the line its edge slides along (the gap to an end
 * point is a perfect square: a double root, which roots/criticalPoint.ts's shortcut settles
 * without probing). Segments must move the discs exactly as infinite lines do while the discs are
 * far from their ends.
 */
function channels(kind: LineKind, motion: "fall" | "slide", n = 24): World {
  const w = new World(motion === "fall" ? { g: 0, gravity: [0, -9.81] } : { g: 9.81, gravity: [0, 0] });
  const L = 1e6;
  for (let k = 0; k <= n; k++) {
    const c = 2 * k - 1;
    if (motion === "fall") w.addLine(`w${k}`, [c, L], [c, -L], kind);
    else w.addLine(`w${k}`, [-L, c], [L, c], kind);
  }
  for (let k = 0; k < n; k++) {
    const along = 3.7 * k;
    if (motion === "fall") w.addBody(`d${k}`, { x: 2 * k, y: along, r: 1, m: 1, vy: -k });
    else w.addBody(`d${k}`, { x: along, y: 2 * k, r: 1, m: 1, mu: 0.01, vx: 300 + 2 * k });
  }
  return w;
}

/** Every event of the run (kind, ids, time, point, normal, impulse) and the bodies at its end. */
function run(w: World, untilTime: number): { events: unknown[]; bodies: unknown[] } {
  const events: unknown[] = [];
  w.advance({ untilTime, maxEvents: 100_000 }, (e) => {
    events.push([e.kind, e.a, e.b, e.time, e.px, e.py, e.nx, e.ny, e.impulse]);
  });
  return { events, bodies: w.bodies() };
}

describe("a disc in a channel exactly its diameter wide", () => {
  it("falls along segments as along lines: untouched, straight down", () => {
    const seg = run(channels("segment", "fall"), 200);
    const line = run(channels("line", "fall"), 200);
    expect(seg).toEqual(line);
    expect(seg.events).toEqual([]);
    const w = channels("segment", "fall");
    w.advance({ untilTime: 200 });
    for (const b of w.bodies()) {
      expect(b.x).toBe(2 * Number(b.id.slice(1)));
      expect(b.vx).toBe(0);
      expect(b.y).toBeLessThan(-190_000);
    }
  });

  it("slides with friction along segments as along lines, to the same stops", () => {
    const seg = run(channels("segment", "slide"), 1e5);
    const line = run(channels("line", "slide"), 1e5);
    expect(seg).toEqual(line);
    expect(seg.events.length).toBe(24);
    for (const e of seg.events) expect((e as unknown[])[0]).toBe("stop");
  });
});
