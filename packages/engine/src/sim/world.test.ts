// Reference scenarios with exact answers (see shared reference-cases): the World's behaviour.
import { describe, expect, it } from "vitest";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

function record(world: World, limits: { untilTime?: number; maxEvents?: number } = {}): WorldEvent[] {
  const log: WorldEvent[] = [];
  world.advance(limits, (e) => log.push({ ...e }));
  return log;
}

describe("World reference scenarios", () => {
  it("the original's sample: one collision at t = 100 - sqrt(9700)", () => {
    const w = new World({ g: 1 });
    w.addBody("A", { x: 350, y: 200, r: 100, m: 10, mu: 1 });
    w.addBody("B", { x: 700, y: 200, r: 100, m: 10, mu: 1, vx: -100 });
    const log = record(w);
    const hits = log.filter((e) => e.kind === "bodyBody");
    expect(hits).toHaveLength(1);
    const exact = 100 - Math.sqrt(9700);
    expect(Math.abs((hits[0] as WorldEvent).time - exact)).toBeLessThanOrEqual(4 * Number.EPSILON * exact);
    const a = w.body("A");
    const b = w.body("B");
    expect(b.vx).toBe(0);
    expect(a.vx).toBe(0); // A stops later too (friction); it moved left
    expect(a.x).toBeLessThan(350);
    expect(b.x).toBeCloseTo(550, 6);
  });

  it("friction stop: exact time and place", () => {
    const w = new World({ g: 10 });
    w.addBody("d", { x: 0, y: 0, r: 1, m: 1, mu: 0.5, vx: 3, vy: 4 });
    w.advance({ untilTime: 0.5 });
    const half = w.body("d");
    expect(half.x).toBeCloseTo(1.125, 14);
    expect(half.y).toBeCloseTo(1.5, 14);
    expect(half.vx).toBeCloseTo(1.5, 14);
    expect(half.vy).toBeCloseTo(2, 14);
    const log = record(w);
    expect(log.map((e) => e.kind)).toEqual(["stop"]);
    expect((log[0] as WorldEvent).time).toBe(1);
    const end = w.body("d");
    expect(end.x).toBeCloseTo(1.5, 14);
    expect(end.y).toBeCloseTo(2, 14);
    expect([end.vx, end.vy]).toEqual([0, 0]);
  });

  it("head-on pair: exact collision time and exchanged velocities", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody("b", { x: 10, y: 0, r: 1, m: 1, vx: -1 });
    const log = record(w);
    expect(log).toHaveLength(1);
    expect((log[0] as WorldEvent).time).toBe(4);
    expect(w.body("a").vx).toBe(-1);
    expect(w.body("b").vx).toBe(1);
  });

  it("Newton's cradle: only the last disc leaves, with the striker's speed", () => {
    const w = new World({ g: 0 });
    for (let i = 0; i < 5; i++) w.addBody(`c${i}`, { x: 2 * i, y: 0, r: 1, m: 1 });
    w.addBody("striker", { x: -6, y: 0, r: 1, m: 1, vx: 4 });
    const log = record(w);
    expect(log.filter((e) => e.kind === "bodyBody")).toHaveLength(5);
    for (const id of ["striker", "c0", "c1", "c2", "c3"]) expect(w.body(id).vx).toBe(0);
    expect(w.body("c4").vx).toBe(4);
    expect(w.body("c4").vy).toBe(0);
  });

  it.each([1, 2, 3, 4, 5, 6])("Galperin's billiard counts the first %i digits of pi", (n) => {
    const digits = "3141592653";
    const w = new World({ g: 0 });
    w.addLine("wall", [0, -10], [0, 10], "line");
    w.addBody("small", { x: 5, y: 0, r: 1, m: 1 });
    w.addBody("big", { x: 10, y: 0, r: 1, m: 100 ** (n - 1), vx: -1 });
    const res = w.advance({});
    expect(res.reason).toBe("idle");
    expect(String(res.events)).toBe(digits.slice(0, n));
  });

  it("a disc bounces inside a box of segments and never leaves", () => {
    const w = new World({ g: 0 });
    w.addLine("s", [0, 0], [10, 0], "segment");
    w.addLine("e", [10, 0], [10, 10], "segment");
    w.addLine("n", [10, 10], [0, 10], "segment");
    w.addLine("w", [0, 10], [0, 0], "segment");
    w.addBody("d", { x: 5, y: 5, r: 0.5, m: 1, vx: 3.3, vy: 1.7 });
    const log = record(w, { maxEvents: 1000 });
    expect(log).toHaveLength(1000);
    for (const e of log) expect(e.kind).toBe("bodyLine");
    const d = w.body("d");
    expect(d.x).toBeGreaterThanOrEqual(0.5 - 1e-9);
    expect(d.x).toBeLessThanOrEqual(9.5 + 1e-9);
    expect(Math.hypot(d.vx, d.vy)).toBeCloseTo(Math.hypot(3.3, 1.7), 12);
  });

  it("segment end points are solid", () => {
    const w = new World({ g: 0 });
    w.addLine("seg", [0, 0], [0, 10], "segment");
    w.addBody("d", { x: -5, y: 10.5, r: 1, m: 1, vx: 1 });
    const log = record(w);
    expect(log).toHaveLength(1);
    expect((log[0] as WorldEvent).px).toBe(0);
    expect((log[0] as WorldEvent).py).toBe(10);
  });
});
