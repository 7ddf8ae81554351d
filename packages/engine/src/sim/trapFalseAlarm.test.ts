// Near-Zeno scenes that are no Zeno state: a disc rattling ever faster between a moving immovable
// disc and what it is pressed against, where the pocket never closes. Neither the trap watch
// (trapWatch.ts) nor the Zeno watch's windows may report them; each runs on to its limit.
import { describe, expect, it } from "vitest";
import { pit } from "./testSupport.js";
import { World } from "./world.js";

const INF = Number.POSITIVE_INFINITY;

/** Advance, counting the events and those between the bodies `a` and `b`. */
function run(w: World, limits: { maxEvents?: number; untilTime?: number }, a = "", b = "") {
  let pair = 0;
  const r = w.advance(limits, (e) => {
    if ((e.a === a && e.b === b) || (e.a === b && e.b === a)) pair++;
  });
  return { ...r, pair };
}

describe("an immovable disc that friction stops just short of crushing a disc", () => {
  it("into a corner, 5e-4 r short (under ZENO_TRAP_GAP): the pocket never closes", () => {
    // Floor and wall meet at the origin; the disc's corner spot is (1, 1). P (R 1, speed 2 along the
    // diagonal, mu 0.5 in the field g = 1) stops with its centre 2 + 5e-4 from the spot.
    const w = new World({ g: 1 });
    w.addLine("floor", [0, 0], [40, 0], "segment");
    w.addLine("wall", [0, 0], [0, 40], "segment");
    w.addBody("d", { x: 1.3, y: 1.1, r: 1, m: 1, mu: 0, vx: 0.3, vy: 0.1 });
    const c = Math.SQRT1_2;
    const stop = 1 + (2 + 5e-4) * c;
    w.addBody("p", { x: stop + 4 * c, y: stop + 4 * c, r: 1, m: INF, mu: 0.5, vx: -2 * c, vy: -2 * c });
    const r = run(w, { maxEvents: 400_000 }, "d", "p");
    // P stopped (at event 288,208); the disc rattles on in the closed pocket, for ever but not
    // converging: events keep their pace once nothing moves the pocket's sides.
    expect(r).toMatchObject({ events: 400_000, reason: "events" });
    expect(r.pair).toBeGreaterThan(100_000);
    const p = w.body("p");
    expect([p.vx, p.vy]).toEqual([0, 0]);
    expect(Math.hypot(p.x - 1, p.y - 1)).toBeCloseTo(2 + 5e-4, 12);
  });

  it("against a wall (all on one line), 1e-3 r short", () => {
    const w = new World({ g: 1 });
    w.addLine("wall", [0, -10], [0, 10], "line");
    w.addBody("d", { x: 2, y: 0, r: 1, m: 1, mu: 0, vx: -1 });
    w.addBody("p", { x: 7.001, y: 0, r: 1, m: INF, mu: 0.5, vx: -2 });
    const r = run(w, { maxEvents: 300_000 }, "d", "p");
    expect(r).toMatchObject({ events: 300_000, reason: "events" });
    expect(r.pair).toBeGreaterThan(100_000);
    expect(w.body("p")).toMatchObject({ x: 3.0010000000000345, vx: 0 });
  });
});

describe("an immovable disc that comes close to closing a pocket but leaves it open", () => {
  it("passing over a pit on a parabola 5e-4 r above closing it: the disc rattles, then is let go", () => {
    const w = pit(5e-4);
    const r = run(w, {}, "d", "p");
    expect(r.reason).toBe("idle");
    // 43,111 events, 16,559 of them between the disc and P (the trap watch tried them).
    expect(r.events).toBeGreaterThan(20_000);
    expect(r.pair).toBeGreaterThan(10_000);
  });

  it("striking the pocket's sides (two immovable discs) 2e-5 before it would close the pocket", () => {
    // The sides at (±a, 0) with a such that P (R 1, coming down at x = 0) touches them, at
    // sqrt(4 - a²), 2e-5 above where it would close the pocket on the disc (r 0.2), at
    // sqrt(1.44 - a²) + 1.2. Its path to the closing meets the sides: no proof (with the trap
    // watch's check of P's path left out, this was reported at event 3,585).
    const f = (a: number) => Math.sqrt(4 - a * a) - Math.sqrt(1.44 - a * a) - 1.2;
    let lo = 1;
    let hi = 1.19;
    for (let i = 0; i < 200; i++) {
      const m = (lo + hi) / 2;
      if (f(m) < 2e-5) lo = m;
      else hi = m;
    }
    const a = (lo + hi) / 2;
    const w = new World({ g: 0 });
    w.addBody("L", { x: -a, y: 0, r: 1, m: INF });
    w.addBody("R", { x: a, y: 0, r: 1, m: INF });
    w.addBody("d", { x: 0.013, y: Math.sqrt(1.44 - a * a) + 0.25, r: 0.2, m: 1 });
    w.addBody("P", { x: 0, y: 3, r: 1, m: INF, vy: -1 });
    const r = run(w, {}, "d", "P");
    expect(r.reason).toBe("idle");
    expect(r.events).toBeGreaterThan(20_000);
    expect(r.pair).toBeGreaterThan(10_000);
  });
});

describe("pockets that are no pockets", () => {
  it("a ball under gravity in a box with a floor of 40 jointed segments, an immovable disc bouncing on a joint", () => {
    const w = new World({ g: 0, gravity: [0, -9.81] });
    for (let i = -20; i < 20; i++)
      w.addLine(`f${String(i + 20).padStart(2, "0")}`, [i, 0], [i + 1, 0], "segment");
    w.addLine("west", [-20, 0], [-20, 30], "segment");
    w.addLine("east", [20, 0], [20, 30], "segment");
    w.addLine("roof", [-20, 30], [20, 30], "segment");
    w.addBody("ball", { x: 0.9, y: 1, r: 0.3, m: 1, vx: 2.3 });
    w.addBody("p", { x: 0, y: 3, r: 0.5, m: INF });
    const r = run(w, { untilTime: 2000 }, "ball", "p");
    expect(r.reason).toBe("time");
    // 9,648 events, 274 of them between the ball and P.
    expect(r.events).toBeGreaterThan(5000);
    expect(r.pair).toBeGreaterThan(100);
  });

  it("a disc in a dead-end channel 2r + 1e-12 wide, an immovable disc following it in and stopping", () => {
    const eps = 1e-12;
    const w = new World({ g: 1 });
    w.addLine("lower", [0, 0], [50, 0], "segment");
    w.addLine("upper", [0, 2 + eps], [50, 2 + eps], "segment");
    w.addLine("end", [0, 0], [0, 2 + eps], "segment");
    w.addBody("d", { x: 5, y: 1 + eps / 2, r: 1, m: 1, mu: 0, vx: -1 });
    w.addBody("p", { x: 12, y: 1 + eps / 2, r: 1, m: INF, mu: 0.5, vx: -2 });
    const r = run(w, { untilTime: 1000 }, "d", "p");
    expect(r.reason).toBe("time");
    expect(r.pair).toBeGreaterThan(90);
    expect(w.body("p")).toMatchObject({ x: 8, vx: 0 });
  });
});
