// The trap watch on pockets other than a corner of two lines (those: trapWatch.test.ts): a disc shut
// in by a moving immovable disc between two immovable discs at rest, at the dead end of a channel
// (three still sides), or in a pit the crusher dips into, is reported within thousands of events,
// naming the disc, the crusher and the sides in its message and its ids.
import { describe, expect, it } from "vitest";
import { SimulationError } from "./errors.js";
import { TRAP_REPORT_BOUND as BOUND, pit, runToError } from "./testSupport.js";
import { World } from "./world.js";

describe(`other pockets an immovable disc closes on a disc are reported within ${BOUND} events`, () => {
  it("a corner of two immovable discs at rest, the crusher coming down between them (no gravity)", () => {
    const w = new World({ g: 0 });
    w.addBody("L", { x: -1.2, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("R", { x: 1.2, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("d", { x: 0.05, y: 1.2, r: 0.5, m: 1, vx: 0.05, vy: 0.02 });
    w.addBody("P", { x: 0, y: 6, r: 1, m: Number.POSITIVE_INFINITY, vy: -1 });
    const { error, events } = runToError(w);
    expect(error).toBeInstanceOf(SimulationError);
    expect((error as Error).message).toMatch(
      /^body "d" is shut in by the immovable body "P", the immovable body "[LR]" and the immovable body "[LR]"/,
    );
    // the immovable sides are bodies: named after the disc and the crusher
    expect([...(error as SimulationError).ids.slice(2)].sort()).toEqual(["L", "R"]);
    expect((error as SimulationError).ids.slice(0, 2)).toEqual(["d", "P"]);
    expect(events).toBeLessThanOrEqual(BOUND);
    // The pocket closes when P's centre is 1.5 above the wedged spot (0, 0.9): at t = 3.6.
    expect(w.time).toBeLessThan(3.6);
    expect(w.time).toBeGreaterThan(3.599);
  });

  it("the dead end of a channel 2r + 1e-3 wide, the crusher coming along it (three still sides)", () => {
    const w = new World({ g: 0 });
    w.addLine("lower", [0, 0], [50, 0], "segment");
    w.addLine("upper", [0, 2.001], [50, 2.001], "segment");
    w.addLine("end", [0, 0], [0, 2.001], "segment");
    w.addBody("d", { x: 5, y: 1.0005, r: 1, m: 1, vx: -1, vy: 0.3 });
    w.addBody("p", { x: 12, y: 1.0005, r: 1, m: Number.POSITIVE_INFINITY, vx: -1 });
    const { error, events } = runToError(w);
    expect(error).toBeInstanceOf(SimulationError);
    expect((error as Error).message).toMatch(
      /^body "d" is shut in by the immovable body "p", line "lower", line "end" and line "upper"/,
    );
    expect(events).toBeLessThanOrEqual(10_000); // 8,192 (2.2 million before)
    // P reaches 2 from the end's corners (1, 1), (1, 1.001) at t = 9 (less a hair of the room).
    expect(w.time).toBeLessThan(9);
    expect(w.time).toBeGreaterThan(8.99);
  });

  it("a pit (a V of two segments) that an immovable disc dips into on its parabola", () => {
    const w = pit(-1e-2);
    const { error, events } = runToError(w);
    expect(error).toBeInstanceOf(SimulationError);
    expect((error as Error).message).toMatch(
      /^body "d" is shut in by the immovable body "p", line "(left|right)"/,
    );
    expect(events).toBeLessThanOrEqual(BOUND);
  });
});
