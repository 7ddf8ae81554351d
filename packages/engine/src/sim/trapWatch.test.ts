// The trap watch through the World and the Timeline: a disc crushed by a moving immovable disc in a
// pocket (a corner of two lines, a wall and a floor, two immovable discs, a pit, a dead end) is
// reported within thousands of events; the windows' convergence test took 2.2 to 2.4 million (5 to
// 19 s here) on each of these scenes. The near misses that must not be reported are in trapFalseAlarm.test.ts.
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../scene/types.js";
import { Timeline } from "../timeline/timeline.js";
import { SimulationError } from "./errors.js";
import type { LineKind } from "./obstacles.js";
import { pit } from "./testSupport.js";
import { World } from "./world.js";

/** The bound this file asserts on events before a crush is reported (measured: 256 to 2,560; the dead end 8,192). */
const BOUND = 5000;

interface CornerOptions {
  /** Gravity (downwards); 0 for none. */
  g?: number;
  /** Without gravity: P's speed. */
  speed?: number;
  /** Direction P comes from, in degrees (default: the corner's bisector). */
  approach?: number;
  /** Angle between the floor and the wall, in degrees. */
  corner?: number;
  floorKind?: LineKind;
  wallKind?: LineKind;
  r?: number;
  R?: number;
  /** Friction field (P then decelerates: mu 0.2 on P, 0 on the disc). */
  friction?: number;
}

/**
 * A disc d (radius r) in the corner of a floor (from the origin along +x) and a wall (from the
 * origin at `corner` degrees), near its corner spot (touching both); an immovable disc p (radius R)
 * that reaches the spot's contact along `approach` at time T, when the pocket closes: falling from
 * rest under gravity g (T = sqrt(6 / g)), or at `speed` without it (T = 3 / speed). Returns the
 * World and T.
 */
function cornerCrush(o: CornerOptions = {}): { world: World; crushAt: number } {
  const g = o.g ?? 10;
  const r = o.r ?? 1;
  const R = o.R ?? 1;
  const cornerDeg = o.corner ?? 90;
  const half = ((cornerDeg / 2) * Math.PI) / 180;
  const a = ((o.approach ?? cornerDeg / 2) * Math.PI) / 180;
  const w = new World({ g: o.friction ?? 0, gravity: [0, -g] });
  const c = Math.cos((cornerDeg * Math.PI) / 180);
  const s = Math.sin((cornerDeg * Math.PI) / 180);
  w.addLine("floor", [0, 0], [40, 0], o.floorKind ?? "segment");
  w.addLine("wall", [0, 0], [40 * c, 40 * s], o.wallKind ?? "segment");
  // The corner spot: on the bisector, r / sin(half) from the corner.
  const sx = (r / Math.sin(half)) * Math.cos(half);
  const sy = r;
  w.addBody("d", { x: sx + 0.3 * Math.cos(half), y: sy + 0.3 * Math.sin(half), r, m: 1, mu: 0 });
  // P's centre when the pocket closes: r + R from the spot along `approach`.
  const tx = sx + (r + R) * Math.cos(a);
  const ty = sy + (r + R) * Math.sin(a);
  const T = g > 0 ? Math.sqrt(6 / g) : 3 / (o.speed ?? 1);
  // With gravity P falls from rest and arrives along -approach: speed g T / sin(a).
  const speed = g > 0 ? (g * T) / Math.sin(a) : (o.speed ?? 1);
  const vx = -speed * Math.cos(a);
  const vy = -speed * Math.sin(a);
  const vy0 = g > 0 ? 0 : vy;
  const mu = o.friction === undefined ? 0 : 0.2;
  // Under friction P starts faster, so as to arrive with the same velocity (decel mu * friction).
  const boost = o.friction === undefined ? 0 : mu * o.friction * T;
  const ux = Math.cos(a);
  const uy = Math.sin(a);
  const x0 = tx - vx * T + (boost * ux * T) / 2;
  const y0 = g > 0 ? ty + 0.5 * g * T * T : ty - vy * T + (boost * uy * T) / 2;
  w.addBody("p", {
    x: x0,
    y: y0,
    r: R,
    m: Number.POSITIVE_INFINITY,
    mu,
    vx: vx - boost * ux,
    vy: vy0 - (g > 0 ? 0 : boost * uy),
  });
  return { world: w, crushAt: T };
}

/** Advance until the World throws; the error and the events counted before it. */
function runToError(w: World): { error: unknown; events: number } {
  let events = 0;
  try {
    w.advance({ maxEvents: 10_000_000 }, () => events++);
  } catch (error) {
    return { error, events };
  }
  return { error: null, events };
}

/** Distance between the centres of two of the World's bodies. */
function apart(w: World, a: string, b: string): number {
  const p = w.body(a);
  const q = w.body(b);
  return Math.hypot(p.x - q.x, p.y - q.y);
}

describe(`a disc crushed into a corner by an immovable disc is reported within ${BOUND} events`, () => {
  const cases: [string, CornerOptions][] = [
    ["two segments at a right angle, the crusher falling in under gravity along the bisector", {}],
    ["no gravity, speed 1", { g: 0 }],
    ["no gravity, speed 100", { g: 0, speed: 100 }],
    ["no gravity, speed 0.01", { g: 0, speed: 0.01 }],
    ["no gravity, the crusher slowed by friction", { g: 0, friction: 0.5 }],
    ["approach at 30°", { approach: 30 }],
    ["approach at 60°", { approach: 60 }],
    ["approach at 80°", { approach: 80 }],
    ["gravity 1", { g: 1 }],
    ["gravity 1000", { g: 1000 }],
    ["a corner of 60°", { corner: 60 }],
    ["a corner of 120°", { corner: 120 }],
    ["a corner of 150°", { corner: 150 }],
    ["two infinite lines", { floorKind: "line", wallKind: "line" }],
    ["two rays", { floorKind: "ray", wallKind: "ray" }],
    ["a wall (a line) on a floor (a segment), a crusher of radius 1.5", { wallKind: "line", R: 1.5 }],
    ["a crusher of radius 4", { R: 4 }],
    ["a disc of radius 0.2", { r: 0.2 }],
  ];
  it.each(cases)("%s", (_, o) => {
    const { world: w, crushAt } = cornerCrush(o);
    const { error, events } = runToError(w);
    expect(error).toBeInstanceOf(SimulationError);
    const e = error as SimulationError;
    expect(e.message).toMatch(
      /^body "d" is shut in by the immovable body "p", line "(floor|wall)" and line "(floor|wall)", which close on it by t=\S+: infinitely many collisions before then \(a Zeno state: a disc crushed by an immovable body\)/,
    );
    expect(e.message).toMatch(/"floor".*"wall"|"wall".*"floor"/);
    // ids: the disc, the crusher, then the sides in the order the message names them; then what to do
    const sides = [...e.message.matchAll(/line "(\w+)"/g)].map((m) => m[1]);
    expect(e.ids).toEqual(["d", "p", ...sides.slice(0, 2)]);
    expect([...e.ids].sort()).toEqual(["d", "floor", "p", "wall"]);
    expect(e.message).toMatch(
      /: to go on, stop the immovable body "p" \(or turn it away\) before t=\S+, give it a finite mass, or remove one of line "(floor|wall)" and line "(floor|wall)"$/,
    );
    expect(events).toBeLessThanOrEqual(BOUND);
    // Met just before the crush (within a thousandth of its time), where the World stopped.
    expect(e.time).toBe(w.time);
    expect(w.time).toBeLessThan(crushAt);
    expect(w.time).toBeGreaterThan(crushAt * (1 - 1e-3));
    // What was computed stays readable: the disc still apart from the crusher.
    expect(apart(w, "d", "p")).toBeGreaterThanOrEqual((w.body("d").r + w.body("p").r) * (1 - 1e-12));
  });
});

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

describe("the report is a state of the simulation, the same however it is reached", () => {
  it("retried, asked by nextEventTime, or met by a copy made on the way: the same event and message", () => {
    const { world: w } = cornerCrush();
    w.advance({ maxEvents: 300 });
    const copy = w.clone();
    const first = runToError(w);
    expect(first.error).toBeInstanceOf(SimulationError);
    const message = (first.error as Error).message;
    const time = w.time;
    // Retrying throws the same at once, counting nothing; so does nextEventTime.
    const again = runToError(w);
    expect((again.error as Error).message).toBe(message);
    expect(again.events).toBe(0);
    expect(() => w.nextEventTime()).toThrow(message);
    expect(w.time).toBe(time);
    const fromCopy = runToError(copy);
    expect((fromCopy.error as Error).message).toBe(message);
    expect(fromCopy.events).toBe(first.events);
    expect(copy.time).toBe(time);
  });

  it("a Timeline keeps the history up to it, computed in one go or in steps", () => {
    const { world } = cornerCrush();
    const scene: SceneFile = {
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, -10],
      actions: [
        ...world
          .lines()
          .map((l) => ({ time: 0, type: "addLine" as const, id: l.id, p1: l.p1, p2: l.p2, kind: l.kind })),
        ...world.bodies().map((b) => ({
          time: 0,
          type: "addBody" as const,
          id: b.id,
          x: b.x,
          y: b.y,
          r: b.r,
          m: b.m,
          mu: b.mu,
          v: [b.vx, b.vy] as [number, number],
        })),
      ],
    };
    const whole = Timeline.fromScene(scene);
    expect(() => whole.prolong({})).toThrow(SimulationError);
    const steps = Timeline.fromScene(scene);
    let error: unknown = null;
    for (let i = 0; i < 100 && error === null; i++)
      try {
        steps.prolong({ events: 37 });
      } catch (e) {
        error = e;
      }
    expect(error).toBeInstanceOf(SimulationError);
    expect(steps.horizon).toBe(whole.horizon);
    expect(steps.eventCount).toBe(whole.eventCount);
    expect(whole.horizon).toBeLessThan(Math.sqrt(0.6));
    expect(whole.stateAt(whole.horizon).bodies.map((b) => b.id)).toEqual(["d", "p"]);
  });
});
