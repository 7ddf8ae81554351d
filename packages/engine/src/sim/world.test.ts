// Reference scenarios with exact answers (see shared reference-cases): the World's behaviour.
import { describe, expect, it } from "vitest";
import { ChapgameError, SimulationError } from "./errors.js";
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
    // Every value here is a short binary fraction, so the exact model gives it bit for bit.
    const half = w.body("d");
    expect([half.x, half.y, half.vx, half.vy, half.ax, half.ay]).toEqual([1.125, 1.5, 1.5, 2, -3, -4]);
    const log = record(w);
    expect(log.map((e) => e.kind)).toEqual(["stop"]);
    expect((log[0] as WorldEvent).time).toBe(1);
    const end = w.body("d");
    expect([end.x, end.y, end.vx, end.vy, end.ax, end.ay]).toEqual([1.5, 2, 0, 0, 0, 0]);
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

describe("the original's Brownian test", () => {
  // Bodies 5, 6, 7, 8 and 15 are dropped: they start overlapping (the original ignored that).
  const data = `4 427.7327025816291 410.8731567269499 0.86271078967411086 19.716205904959949
9 479.47322517677304 497.77954130594941 -70.303234441621157 0.056963218149206796
10 542.91588368371879 551.71588572974224 -4.453993382294243 29.758713432305768
11 510.69929211029961 438.94058675099257 40.306986579592632 93.7478943811206
12 545.39242067561509 514.22261429002583 -9.77745919722733 54.647713187155034
13 577.26895055792966 421.40130336625805 13.985886448574774 -55.37645958343419
14 465.65072596185382 569.62070100613278 -25.134243364819696 58.470190427253272
16 432.28503471693551 442.48121322319111 17.435810081585586 45.037624663398276
17 518.82655460404681 565.76523335009551 46.805198499496925 -52.838994586484276
18 435.13704109597023 517.22696014545977 0.94714408290828089 74.513907127285449`;

  it("first event is bodies 10 and 17 at the original's time, with its velocities", () => {
    const w = new World({ g: 1 });
    w.addLine("l1", [400, 400], [400, 600], "segment");
    w.addLine("l2", [400, 400], [600, 400], "segment");
    w.addLine("l3", [600, 600], [400, 600], "segment");
    w.addLine("l4", [600, 600], [600, 400], "segment");
    for (const line of data.split("\n")) {
      const [id, x, y, vx, vy] = line.trim().split(/\s+/);
      w.addBody(id as string, { x: Number(x), y: Number(y), vx: Number(vx), vy: Number(vy), r: 10, m: 1 });
    }
    const log = record(w, { maxEvents: 1 });
    const e = log[0] as WorldEvent;
    expect([e.kind, e.a, e.b]).toEqual(["bodyBody", "10", "17"]);
    expect(Math.abs(e.time - 0.097649490379264084)).toBeLessThan(1e-12);
    const b10 = w.body("10");
    const b17 = w.body("17");
    expect(b10.vx).toBeCloseTo(65.7970158510537, 9);
    expect(b10.vy).toBeCloseTo(7.731626502425069, 9);
    expect(b17.vx).toBeCloseTo(-23.445810733851019, 9);
    expect(b17.vy).toBeCloseTo(-30.811907656603577, 9);
  });
});

describe("time reversal", () => {
  it("an elastic scene run forward, velocities flipped and run again returns to its start", () => {
    const start = [
      { id: "a", x: 0, y: 0, vx: 3, vy: 0.5 },
      { id: "b", x: 10, y: 1, vx: -2, vy: 0 },
      { id: "c", x: 5, y: 8, vx: 0, vy: -2.5 },
      { id: "d", x: -6, y: -6, vx: 1.5, vy: 2.5 },
      { id: "e", x: -8, y: 7, vx: 2.2, vy: -1.1 },
    ];
    const box = (world: World): void => {
      world.addLine("s", [-12, -12], [12, -12], "segment");
      world.addLine("e", [12, -12], [12, 12], "segment");
      world.addLine("n", [12, 12], [-12, 12], "segment");
      world.addLine("w", [-12, 12], [-12, -12], "segment");
    };
    const w = new World({ g: 0 });
    box(w);
    for (const b of start) w.addBody(b.id, { ...b, r: 1, m: 1 });
    const T = 30;
    const forward = record(w, { untilTime: T });
    expect(forward.filter((e) => e.kind === "bodyBody").length).toBeGreaterThan(4);
    const back = new World({ g: 0, time: T });
    box(back);
    for (const b of w.bodies()) back.addBody(b.id, { x: b.x, y: b.y, vx: -b.vx, vy: -b.vy, r: b.r, m: b.m });
    back.advance({ untilTime: 2 * T });
    // Disc–disc collisions amplify round-off (the dynamics are chaotic), so a few dozen
    // collisions leave ~1e-9 of drift: far below any visible scale, far above one ulp.
    for (const b of start) {
      const e = back.body(b.id);
      expect(e.x).toBeCloseTo(b.x, 6);
      expect(e.y).toBeCloseTo(b.y, 6);
      expect(e.vx).toBeCloseTo(-b.vx, 6);
    }
  });
});

describe("Zeno states are reported, not looped over", () => {
  // Regression (found by the timeline's fuzzer): the light disc is crushed between an immovable
  // disc and the wall; its collisions converge on the crush time at distinct instants.
  it("a disc crushed between an immovable disc and a wall", () => {
    const w = new World({ g: 1.32 });
    w.addLine("s", [0, 0], [20, 0], "segment");
    w.addLine("e", [20, 0], [20, 20], "segment");
    w.addLine("n", [20, 20], [0, 20], "segment");
    w.addLine("w", [0, 20], [0, 0], "segment");
    w.addBody("b0", { x: 3, y: 3, r: 0.3, m: 4.58, mu: 1, vx: 0.96 });
    w.addBody("b1", { x: 7, y: 3, r: 0.687, m: Number.POSITIVE_INFINITY, vx: -5 });
    // Bounded: with the wall missed (a broken broad phase) the immovable disc pushes the light one
    // along for ever, and an unbounded advance made this test hang instead of fail.
    expect(() => w.advance({ untilTime: 10 })).toThrow(SimulationError);
    expect(w.time).toBeGreaterThan(1.1425);
    expect(w.time).toBeLessThan(1.1426);
  });

  it("a disc resting on a floor under gravity", () => {
    const w = new World({ g: 0, gravity: [0, -10] });
    w.addLine("floor", [-10, 0], [10, 0], "segment");
    w.addBody("ball", { x: 0, y: 1, r: 1, m: 1 });
    expect(() => w.advance({ untilTime: 1 })).toThrow(/resting contact/);
  });
});

describe("body(id, t) keeps to the current motion", () => {
  it("a time before the body's last event is refused naming t, not extrapolated through the wall", () => {
    // The audit's case: the disc bounces off the wall at x = 10 at t = 9; at t = 5 it was at x = 5,
    // but the post-bounce motion extrapolated back gave x = 13, beyond the wall.
    const w = new World({ g: 0 });
    w.addLine("wall", [10, -5], [10, 5], "line");
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    w.advance({ untilTime: 12 });
    expect(w.motion("a").t0).toBe(9);
    expect(() => w.body("a", 5)).toThrow(
      /^t: must be a time at or after body "a"'s last event or edit, t0 = 9 \(got 5\)/,
    );
    expect(() => w.bodies(8.5)).toThrow(ChapgameError);
    expect(() => w.body("a", Number.NaN)).toThrow(ChapgameError);
    expect(w.body("a", 9).x).toBe(9);
    expect(w.body("a").x).toBe(6);
  });
});

describe("read-only state", () => {
  it("time, g and the gravity field cannot be assigned (the audit's w.time = -100 ran from a wrong state)", () => {
    const w = new World({ g: 2, gravity: [0, 0] });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1, mu: 0.1 });
    w.advance({ untilTime: 1 });
    const loose = w as unknown as Record<string, number>;
    for (const key of ["time", "g", "gx", "gy"]) expect(() => (loose[key] = -100), key).toThrow(TypeError);
    expect([w.time, w.g, w.gx, w.gy]).toEqual([1, 2, 0, 0]);
    w.setGlobal({ g: 3 });
    expect(w.g).toBe(3);
  });
});
