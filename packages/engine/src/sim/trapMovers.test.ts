// The trap watch with other immovable discs moving (trapWatch.ts, moversClear): a crush in a pocket
// is proven when none of them can reach the crusher's path or an immovable side before the pocket
// closes (without gravity their speeds are bounded). Before, any other moving immovable disc left
// the crush to the windows' convergence test: 2,399,999 events (4.9 and 7.4 s for the first two
// scenes, measured by hand at commit 8bfd078). A disc that strikes a side and opens the pocket just
// before it closes must not be reported.
import { describe, expect, it } from "vitest";
import { SimulationError } from "./errors.js";
import { runToError } from "./testSupport.js";
import { World } from "./world.js";

const INF = Number.POSITIVE_INFINITY;

/** A disc in the corner of a floor and a wall, P closing it along the diagonal at speed 1 at t = 3. */
function corner(): World {
  const w = new World({ g: 0 });
  w.addLine("floor", [0, 0], [40, 0], "segment");
  w.addLine("wall", [0, 0], [0, 40], "segment");
  w.addBody("d", { x: 1.3, y: 1.1, r: 1, m: 1, vx: 0.3, vy: 0.1 });
  const c = Math.SQRT1_2;
  w.addBody("p", { x: 1 + 5 * c, y: 1 + 5 * c, r: 1, m: INF, vx: -c, vy: -c });
  return w;
}

function expectCornerReport(w: World): number {
  const { error, events } = runToError(w, 4_000_000);
  expect(error).toBeInstanceOf(SimulationError);
  expect((error as Error).message).toMatch(
    /^body "d" is shut in by the immovable body "p", line "(floor|wall)" and line "(floor|wall)", which close on it by t=/,
  );
  expect(w.time).toBeLessThan(3);
  expect(w.time).toBeGreaterThan(3 - 1e-3);
  return events;
}

describe("a crush in a pocket is reported while other immovable discs move (before: 2.4 million events)", () => {
  it("one moving away far from it", () => {
    const w = corner();
    w.addBody("q", { x: 30, y: 30, r: 2, m: INF, vx: 1, vy: 0.5 });
    expect(expectCornerReport(w)).toBeLessThanOrEqual(5000); // 2,561 (before: 2,399,999 events, 4.9 s)
  });

  it("two going to and fro between two walls of their own, striking each other (in either order)", () => {
    const platforms = (order: readonly string[]): World => {
      const w = corner();
      w.addLine("left", [20, 20], [20, 30], "segment");
      w.addLine("right", [35, 20], [35, 30], "segment");
      for (const id of order)
        if (id === "q1") w.addBody("q1", { x: 25, y: 23, r: 1, m: INF, vx: 5 });
        else w.addBody("q2", { x: 30, y: 27, r: 1, m: INF, vx: -3 });
      return w;
    };
    const w = platforms(["q1", "q2"]);
    const events = expectCornerReport(w);
    expect(events).toBeLessThanOrEqual(5000); // 2,560 (before: 2,399,999 events, 7.4 s)
    const other = platforms(["q2", "q1"]);
    expect(expectCornerReport(other)).toBe(events);
    expect(other.time).toBe(w.time);
  });
});

describe("another immovable disc that opens the pocket just before it closes: never reported", () => {
  /**
   * The pocket of two immovable discs L and R at rest, P coming down between them (closing at
   * t = 3.6); with `striker`, an immovable disc coming up from below at speed 10 strikes R 1e-4
   * before that, and R (taking its speed along the normal) moves off up and to the right.
   */
  function pocket(striker: boolean): World {
    const w = new World({ g: 0 });
    w.addBody("L", { x: -1.2, y: 0, r: 1, m: INF });
    w.addBody("R", { x: 1.2, y: 0, r: 1, m: INF });
    w.addBody("d", { x: 0.05, y: 1.2, r: 0.5, m: 1, vx: 0.05, vy: 0.02 });
    w.addBody("P", { x: 0, y: 6, r: 1, m: INF, vy: -1 });
    const c = Math.SQRT1_2;
    const T = 3.6 - 1e-4;
    // The striker's centre at the strike: 1.5 from R's, down and to the left.
    const [sx, sy] = [1.2 - 1.5 * c, -1.5 * c];
    if (striker)
      w.addBody("q", { x: sx - 10 * T * c, y: sy - 10 * T * c, r: 0.5, m: INF, vx: 10 * c, vy: 10 * c });
    return w;
  }

  it("a disc striking a side of the pocket 1e-4 before P would close it", () => {
    // Without the striker: reported (at event 2,305).
    const { error, events } = runToError(pocket(false), 4_000_000);
    expect((error as Error).message).toMatch(/^body "d" is shut in by the immovable body "P"/);
    expect(events).toBeLessThanOrEqual(5000);
    // With it the proof is tried and refused from then on until the strike (at event 10,133): the
    // striker could reach R by the closing. R moves off, the disc gets out, and all goes idle.
    const w = pocket(true);
    let struck = -1;
    let count = 0;
    const r = w.advance({ maxEvents: 1_000_000 }, (e) => {
      count++;
      if (struck < 0 && (e.a === "q" || e.b === "q")) struck = count;
    });
    expect(r.reason).toBe("idle");
    expect(struck).toBeGreaterThan(events);
    expect(w.body("R").vx).toBeGreaterThan(7);
    expect(Math.hypot(w.body("d").x, w.body("d").y)).toBeGreaterThan(3);
  });
});
