// The trap watch on a disc crushed in line (the disc, the crusher and the end all on one line
// parallel to an axis; rows of discs: lineWatch.test.ts): reported within thousands of events (the
// windows' convergence test took 2.4 million), naming the disc, the crusher and the end, whatever
// the time origin.
import { describe, expect, it } from "vitest";
import { SimulationError } from "./errors.js";
import { TRAP_REPORT_BOUND as BOUND, runToError } from "./testSupport.js";
import { World } from "./world.js";

describe("a disc crushed in line (all on one line parallel to an axis; rows of discs: lineWatch.test.ts)", () => {
  /** Advance to the report; its events, after checking that it is the in-line one. */
  function inLine(w: World, end: string): number {
    const { error, events } = runToError(w);
    expect(error).toBeInstanceOf(SimulationError);
    expect((error as Error).message).toMatch(
      new RegExp(
        `^body "\\w+" is crushed in line between the immovable body "\\w+" and ${end}, which close on it by t=`,
      ),
    );
    // ids: the disc, the crusher, then the end
    const [disc, crusher] = [...(error as Error).message.matchAll(/"(\w+)"/g)].map((m) => m[1]);
    const endId = /"(\w+)"/.exec(end)?.[1];
    expect((error as SimulationError).ids).toEqual([disc, crusher, endId]);
    expect((error as Error).message).toMatch(`or remove ${end}`);
    return events;
  }

  it("the editor's crush scene: a disc against a wall (a line), the crusher at speed 1 (before: 2.4 million events)", () => {
    const w = new World({ g: 9.81 });
    w.addLine("wall", [0, -5], [0, 5], "line");
    w.addBody("small", { x: 2, y: 0, r: 1, m: 1 });
    w.addBody("crusher", { x: 5, y: 0, r: 1, m: Number.POSITIVE_INFINITY, vx: -1 });
    expect(inLine(w, 'line "wall"')).toBeLessThanOrEqual(BOUND); // 1,280
    expect(w.time).toBeLessThan(2);
    expect(w.time).toBeGreaterThan(1.998);
  });

  it("a ball bouncing on a floor under gravity, an immovable disc falling on it from straight above", () => {
    const w = new World({ g: 0, gravity: [0, -9.81] });
    w.addLine("floor", [-10, 0], [10, 0], "segment");
    w.addBody("ball", { x: 0, y: 3, r: 1, m: 1 });
    w.addBody("p", { x: 0, y: 8, r: 1, m: Number.POSITIVE_INFINITY });
    expect(inLine(w, 'line "floor"')).toBeLessThanOrEqual(BOUND); // 1,793
  });

  it("a fast disc (10 times the crusher's speed) whatever the time origin", () => {
    for (const t0 of [0, -7]) {
      const w = new World({ g: 0, time: t0 });
      w.addLine("wall", [0, -10], [0, 10], "line");
      w.addBody("d", { x: 5, y: 0, r: 1, m: 1, vx: -10 });
      w.addBody("p", { x: 10, y: 0, r: 1, m: Number.POSITIVE_INFINITY, vx: -1 });
      // 69,377: the disc gains speed from the crusher's every kick; the windows took 2.4 million.
      expect(inLine(w, 'line "wall"')).toBeLessThanOrEqual(100_000);
      expect(w.time).toBeLessThan(t0 + 7);
      expect(w.time).toBeGreaterThan(t0 + 6.998);
    }
  });
});
