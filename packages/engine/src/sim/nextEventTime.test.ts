/**
 * World.nextEventTime: the time of the next collision or stop, found in place without copying the
 * world, changing nothing observable, and throwing what advancing to that event would throw.
 * Random interleavings with edits are in nextEventTime.prop.test.ts.
 */
import { afterEach, describe, expect, it, vi } from "vitest";
import { SimulationError } from "./errors.js";
import { Simulator } from "./simulator.js";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

type Spied = Record<string, (...a: unknown[]) => unknown>;
const spyOnSim = (name: string) => vi.spyOn(Simulator.prototype as unknown as Spied, name);
afterEach(() => vi.restoreAllMocks());

function record(w: World, limits: { untilTime?: number; maxEvents?: number }): WorldEvent[] {
  const log: WorldEvent[] = [];
  w.advance(limits, (e) => log.push({ ...e }));
  return log;
}

/** The error message a call throws (fails the test if it does not throw). */
function thrown(f: () => unknown): string {
  try {
    f();
  } catch (e) {
    return String(e);
  }
  throw new Error("expected a throw");
}

/**
 * 64 × 64 discs at rest on a unit lattice in a box, row 32 left empty: a corridor along which one
 * disc (vx = 2) flies to the east wall, crossing grid cells all the way.
 */
function corridor(): World {
  const w = new World({ g: 0 });
  w.addLine("south", [0, 0], [64, 0], "segment");
  w.addLine("east", [64, 0], [64, 64], "segment");
  w.addLine("north", [64, 64], [0, 64], "segment");
  w.addLine("west", [0, 64], [0, 0], "segment");
  for (let j = 0; j < 64; j++)
    for (let i = 0; i < 64; i++)
      if (j !== 32) w.addBody(`d${j * 64 + i}`, { x: i + 0.5, y: j + 0.5, r: 0.3, m: 1 });
  w.addBody("mover", { x: 0.5, y: 32.5, r: 0.3, m: 1, vx: 2 });
  w.advance({ maxEvents: 0 }); // predictions made, nothing processed
  return w;
}

/** A dilute gas of n unit discs (speed 10, directions from a fixed LCG) in a box. */
function gas(n: number): World {
  let s = 12345;
  const rnd = (): number => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 4294967296;
  };
  const side = Math.sqrt((n * Math.PI) / 0.1);
  const k = Math.ceil(Math.sqrt(n));
  const cell = side / k;
  const w = new World({ g: 0 });
  w.addLine("s", [0, 0], [side, 0], "segment");
  w.addLine("e", [side, 0], [side, side], "segment");
  w.addLine("n", [side, side], [0, side], "segment");
  w.addLine("w", [0, side], [0, 0], "segment");
  for (let i = 0; i < n; i++) {
    const a = 2 * Math.PI * rnd();
    const [x, y] = [((i % k) + 0.5) * cell, (Math.floor(i / k) + 0.5) * cell];
    w.addBody(`g${i}`, { x, y, r: 1, m: 1, vx: 10 * Math.cos(a), vy: 10 * Math.sin(a) });
  }
  return w;
}

describe("World.nextEventTime", () => {
  it("answers +Infinity when nothing will ever happen", () => {
    const empty = new World();
    empty.advance({ maxEvents: 0 });
    expect(empty.nextEventTime()).toBe(Number.POSITIVE_INFINITY);
    const still = new World();
    still.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
    still.addLine("floor", [-5, -1], [5, -1], "segment");
    still.advance({ maxEvents: 0 });
    expect(still.nextEventTime()).toBe(Number.POSITIVE_INFINITY);
    const flying = new World({ g: 0 });
    flying.addBody("away", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    flying.addLine("behind", [-5, -5], [-5, 5], "segment");
    flying.advance({ untilTime: 1 });
    expect(flying.nextEventTime()).toBe(Number.POSITIVE_INFINITY);
  });

  it("a large world is not copied: the peek does only the moving disc's cell crossings", () => {
    const w = corridor();
    const twin = corridor();
    const clone = vi.spyOn(World.prototype, "clone");
    const cross = spyOnSim("processCrossing");
    const predict = spyOnSim("predict");
    const t = w.nextEventTime();
    expect(clone).not.toHaveBeenCalled();
    expect(predict).not.toHaveBeenCalled();
    // The disc crosses many cells before it reaches the wall, and nothing else moves.
    expect(cross.mock.calls.length).toBeGreaterThan(30);
    expect(new Set(cross.mock.calls.map((c) => c[0])).size).toBe(1);
    // The answer is the wall hit (centre at x = 63.7 at t = 63.2 / 2), as the twin processes it.
    expect(t).toBeCloseTo(31.6, 12);
    const [hit] = record(twin, { maxEvents: 1 });
    expect(hit).toMatchObject({ kind: "bodyLine", a: "mover", b: "east", time: t });
    expect(record(w, { maxEvents: 3 })).toStrictEqual([hit, ...record(twin, { maxEvents: 2 })]);
  });

  it("an edit after a peek sees the grid as it is now: a disc added in the corridor is hit", () => {
    // The peek moved the flying disc's grid registration to the far end and back; the new disc
    // is registered against the grid as it is at time 0, so the flying disc finds it on its way.
    const w = corridor();
    const twin = corridor();
    expect(w.nextEventTime()).toBeCloseTo(31.6, 12);
    for (const x of [w, twin]) x.addBody("late", { x: 40.5, y: 32.5, r: 0.3, m: 1 });
    expect(w.nextEventTime()).toBeCloseTo(39.4 / 2, 12);
    const events = record(w, { maxEvents: 4 });
    expect(events).toStrictEqual(record(twin, { maxEvents: 4 }));
    expect(events[0]).toMatchObject({ kind: "bodyBody", a: "late", b: "mover" });
    expect(w.bodies()).toStrictEqual(twin.bodies());
  });

  it("a body that crosses cells and is re-predicted in one peek is put back as it was", () => {
    // 36 discs at rest make the grid active (cells 2.27 wide from x = -2). B, which A was to hit at
    // t = 0.75, is knocked away by C at t = 0.5; after that A's prediction is stale (A and B are
    // neighbours from t = 0.135). The peek then moves A across cells, re-predicts it at 0.75, and
    // ends at A's hit on the east wall (t = 27.5 / 4).
    const make = (): World => {
      const w = new World({ g: 0 });
      w.addLine("floor", [-50, -40], [50, -40], "segment");
      w.addLine("east", [30, -50], [30, 50], "segment");
      for (let i = 0; i < 36; i++)
        w.addBody(`f${i}`, { x: (i % 6) * 2.5, y: 20 + Math.floor(i / 6) * 2.5, r: 1, m: 1 });
      w.addBody("A", { x: 2, y: 0, r: 0.5, m: 1, vx: 4 });
      w.addBody("B", { x: 6, y: 0, r: 0.5, m: 1 });
      w.addBody("C", { x: 6, y: 3, r: 0.5, m: 1, vy: -4 });
      expect(record(w, { maxEvents: 1 })).toMatchObject([{ time: 0.5, a: "B", b: "C" }]);
      return w;
    };
    const w = make();
    const twin = make();
    const cross = spyOnSim("processCrossing");
    const predict = spyOnSim("predict");
    expect(w.nextEventTime()).toBe(6.875);
    const crossed = new Set(cross.mock.calls.map((c) => c[0]));
    expect(predict.mock.calls.length).toBeGreaterThan(0);
    expect(predict.mock.calls.every((c) => crossed.has(c[0]))).toBe(true);
    vi.restoreAllMocks();
    // A disc added in A's path now (t = 0.5, A at x = 4) is hit at t = 0.5 + (20 - 1 - 4) / 4.
    for (const x of [w, twin]) x.addBody("late", { x: 20, y: 0, r: 0.5, m: 1 });
    expect(w.nextEventTime()).toBe(4.25);
    const events = record(w, { maxEvents: 5 });
    expect(events).toStrictEqual(record(twin, { maxEvents: 5 }));
    expect(events[0]).toMatchObject({ time: 4.25, kind: "bodyBody", a: "A", b: "late" });
    expect(w.bodies()).toStrictEqual(twin.bodies());
  });

  it("in a 2,000-disc gas, peeking before every event answers that event's time and changes nothing", () => {
    const w = gas(2000);
    const twin = gas(2000);
    w.advance({ untilTime: 0.2 });
    twin.advance({ untilTime: 0.2 });
    const clone = vi.spyOn(World.prototype, "clone");
    const log: WorldEvent[] = [];
    for (let i = 0; i < 300; i++) {
      const t = w.nextEventTime();
      const [e] = record(w, { maxEvents: 1 });
      expect(e?.time).toBe(t);
      if (e) log.push(e);
    }
    expect(clone).not.toHaveBeenCalled();
    expect(log).toStrictEqual(record(twin, { maxEvents: 300 }));
    expect(w.bodies()).toStrictEqual(twin.bodies());
    expect(w.counts).toStrictEqual(twin.counts);
  });

  it("before predictions are made it answers from a copy, leaving the world's first advance as it was", () => {
    const w = gas(100);
    const twin = gas(100);
    const clone = vi.spyOn(World.prototype, "clone");
    const t = w.nextEventTime();
    expect(clone).toHaveBeenCalledTimes(1);
    const [first] = record(w, { maxEvents: 1 });
    expect(first?.time).toBe(t);
    expect(record(w, { maxEvents: 50 })).toStrictEqual(record(twin, { maxEvents: 51 }).slice(1));
  });

  it("throws the resting-contact error advancing would throw, changing nothing", () => {
    const w = new World({ g: 0, gravity: [0, -10] });
    w.addLine("floor", [-10, 0], [10, 0], "segment");
    w.addBody("ball", { x: 0, y: 1, r: 1, m: 1 });
    w.advance({ maxEvents: 0 });
    const before = w.bodies();
    const message = thrown(() => w.nextEventTime());
    expect(message).toMatch(/resting contact/);
    expect(thrown(() => w.nextEventTime())).toBe(message);
    expect(w.bodies()).toStrictEqual(before);
    expect(w.time).toBe(0);
    expect(thrown(() => w.advance({}))).toBe(message);
  });

  it("throws the Zeno error advancing would throw, changing nothing", () => {
    // A disc touching a wall is pushed by a touching immovable disc: collisions without end at t = 0.
    // Find how many events pass before the watch reports the Zeno state, stop just before, and peek.
    const make = (): World => {
      const w = new World({ g: 0 });
      w.addLine("wall", [0, -5], [0, 5], "segment");
      w.addBody("a", { x: 1, y: 0, r: 1, m: 1 });
      w.addBody("b", { x: 3, y: 0, r: 1, m: Number.POSITIVE_INFINITY, vx: -1 });
      return w;
    };
    const probe = make();
    let k = 0;
    const message = thrown(() => probe.advance({}, () => k++));
    expect(message).toMatch(/Zeno/);
    const w = make();
    w.advance({ maxEvents: k });
    const before = { time: w.time, bodies: w.bodies(), counts: { ...w.counts } };
    expect(() => w.nextEventTime()).toThrow(SimulationError);
    expect(thrown(() => w.nextEventTime())).toBe(message);
    expect({ time: w.time, bodies: w.bodies(), counts: { ...w.counts } }).toStrictEqual(before);
    expect(thrown(() => w.advance({}))).toBe(message);
  });
});
