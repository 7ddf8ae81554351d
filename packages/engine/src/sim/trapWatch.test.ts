// The trap watch through the World and the Timeline: a disc crushed into a corner of two lines by a
// moving immovable disc is reported within thousands of events (the windows' convergence test took
// 2.2 to 2.4 million, 5 to 19 s here, on each of these scenes), at a state of the simulation that is
// the same however it is reached. Other pockets (two immovable discs, a dead end, a pit):
// trapPockets.test.ts; a disc crushed in line: trapInLine.test.ts; near misses that must not be
// reported: trapFalseAlarm.test.ts.
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../scene/types.js";
import { Timeline } from "../timeline/timeline.js";
import { SimulationError } from "./errors.js";
import type { LineKind } from "./obstacles.js";
import { TRAP_REPORT_BOUND as BOUND, runToError } from "./testSupport.js";
import { World } from "./world.js";

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
