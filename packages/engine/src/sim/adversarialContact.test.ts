// Adversarial contact scenes with exact answers: simultaneous contacts (two discs at once, corners,
// seams, a point on a line), friction stops at the instant of a contact, parabolas meeting the ends
// of segments and rays, and immovable bodies. Each is run in several insertion orders, which must
// give the same bits (events and final states).
import { describe, expect, it } from "vitest";
import type { SceneSpec } from "../../test/referenceWorld.js";
import { shuffledOrder, worldFromSpec } from "../../test/worldFromSpec.js";
import { totals } from "./testSupport.js";
import type { BodyState, WorldEvent } from "./types.js";

type Body = SceneSpec["bodies"][number];
const body = (id: string, b: Partial<Body> & { x: number; y: number }): Body => ({
  id,
  vx: 0,
  vy: 0,
  r: 1,
  m: 1,
  mu: 0,
  ...b,
});
const scene = (s: Partial<SceneSpec>): SceneSpec => ({
  g: 0,
  gravity: [0, 0],
  bodies: [],
  lines: [],
  points: [],
  ...s,
});

interface Run {
  events: WorldEvent[];
  bodies: BodyState[];
}

/** Run the scene to `until` in insertion order and in four shuffled orders; all must agree bit for bit. */
function run(spec: SceneSpec, until: number): Run {
  const once = (order?: (n: number) => number[]): Run => {
    const w = worldFromSpec(spec, order);
    const events: WorldEvent[] = [];
    w.advance({ untilTime: until, maxEvents: 10_000 }, (e) => events.push({ ...e }));
    return { events, bodies: w.bodies() };
  };
  const first = once();
  for (const seed of [1, 2, 3, 4])
    expect(once(shuffledOrder(seed)), `insertion order seed ${seed}`).toEqual(first);
  return first;
}

const brief = (e: WorldEvent) => [e.time, e.kind, e.a, e.b, e.impulse];

describe("simultaneous contacts", () => {
  it("a disc hitting two discs at once: energy and momentum kept, mirrored scene mirrored exactly", () => {
    const make = (yp: number) =>
      scene({
        bodies: [
          body("cue", { x: 0, y: 0, vx: 1 }),
          body("p", { x: 4, y: yp, m: 2 }),
          body("q", { x: 4, y: -yp, m: 3 }),
        ],
      });
    const a = run(make(1), 10);
    const b = run(make(-1), 10);
    expect(a.events.map((e) => [e.time, e.a, e.b])).toEqual([
      [4 - Math.sqrt(3), "cue", "p"],
      [4 - Math.sqrt(3), "cue", "q"],
    ]);
    const { energy, px, py } = totals(a.bodies);
    expect(Math.abs(energy - 0.5)).toBeLessThan(1e-15);
    expect(Math.abs(px - 1)).toBeLessThan(1e-15);
    expect(Math.abs(py)).toBeLessThan(1e-15);
    expect(b.bodies.map((s) => [s.x, -s.y, s.vx, -s.vy])).toEqual(
      a.bodies.map((s) => [s.x, s.y, s.vx, s.vy]),
    );
  });

  it("three discs head on at one instant: the outer ones swap velocities", () => {
    const r = run(
      scene({
        bodies: [
          body("A", { x: 0, y: 0, vx: 1 }),
          body("B", { x: 5, y: 0 }),
          body("C", { x: 10, y: 0, vx: -1 }),
        ],
      }),
      10,
    );
    expect(r.events.map(brief)).toEqual([
      [3, "bodyBody", "A", "B", 1],
      [3, "bodyBody", "B", "C", 2],
      [3, "bodyBody", "A", "B", 1],
    ]);
    expect(r.bodies.map((s) => [s.id, s.x, s.vx])).toEqual([
      ["A", -4, -1],
      ["B", 5, 0],
      ["C", 14, 1],
    ]);
  });

  it("into a square corner of two segments: both walls at one instant, straight back", () => {
    const lines: SceneSpec["lines"] = [
      { id: "a", p1: [0, 0], p2: [10, 0], kind: "segment" },
      { id: "b", p1: [0, 0], p2: [0, 10], kind: "segment" },
    ];
    const r = run(scene({ lines, bodies: [body("d", { x: 5, y: 5, vx: -1, vy: -1 })] }), 20);
    expect(r.events.map(brief)).toEqual([
      [4, "bodyLine", "d", "a", 2],
      [4, "bodyLine", "d", "b", 2],
    ]);
    expect(r.bodies[0]).toMatchObject({ x: 17, y: 17, vx: 1, vy: 1 });
  });

  it("onto the shared end of two segments (a convex corner): one impulse along the diagonal", () => {
    const lines: SceneSpec["lines"] = [
      { id: "a", p1: [0, 0], p2: [-10, 0], kind: "segment" },
      { id: "b", p1: [0, 0], p2: [0, -10], kind: "segment" },
    ];
    const r = run(scene({ lines, bodies: [body("d", { x: 5, y: 5, vx: -1, vy: -1 })] }), 20);
    expect(r.events).toHaveLength(1);
    expect(r.events[0]).toMatchObject({ kind: "bodyLine", a: "d", b: "a", px: 0, py: 0 });
    expect(r.events[0]?.time).toBeCloseTo(5 - Math.SQRT1_2, 14);
    expect(r.bodies[0]).toMatchObject({ vx: 1, vy: 1 });
  });

  it("onto the seam of two collinear segments and onto a point lying on a line: one impulse", () => {
    const seam = scene({
      lines: [
        { id: "a", p1: [-10, 0], p2: [0, 0], kind: "segment" },
        { id: "b", p1: [0, 0], p2: [10, 0], kind: "segment" },
      ],
      bodies: [body("d", { x: -3, y: 5, vx: 0.75, vy: -1 })],
    });
    const onLine = scene({
      lines: [{ id: "L", p1: [0, 0], p2: [10, 0], kind: "line" }],
      points: [{ id: "P", p: [5, 0] }],
      bodies: [body("d", { x: 2, y: 5, vx: 0.75, vy: -1 })],
    });
    for (const [s, x] of [
      [seam, 0],
      [onLine, 5],
    ] as const) {
      const r = run(s, 20);
      expect(r.events.map((e) => [e.time, e.kind, e.px, e.py, e.nx, e.ny, e.impulse])).toEqual([
        [4, "bodyLine", x, 0, 0, -1, 2],
      ]);
      expect(r.bodies[0]).toMatchObject({ x: x + 12, y: 17, vx: 0.75, vy: 1 });
    }
  });

  it("sliding along a two-segment floor across the seam: no event", () => {
    const r = run(
      scene({
        lines: [
          { id: "a", p1: [-10, 0], p2: [0, 0], kind: "segment" },
          { id: "b", p1: [0, 0], p2: [10, 0], kind: "segment" },
        ],
        bodies: [body("d", { x: -5, y: 1, vx: 1 })],
      }),
      20,
    );
    expect(r.events).toEqual([]);
    expect(r.bodies[0]).toMatchObject({ x: 15, y: 1, vx: 1, vy: 0 });
  });
});

describe("friction stops at the instant of a contact", () => {
  // v = 2, mu g = 1: the disc stops after 2 at t = 2, exactly touching what is there.
  const stopper = body("A", { x: 0, y: 0, mu: 1, vx: 2 });
  it("touching a disc, a wall, a point, a segment's end: a stop and nothing else", () => {
    const others: Partial<SceneSpec>[] = [
      { bodies: [stopper, body("B", { x: 4, y: 0 })] },
      { bodies: [stopper], lines: [{ id: "W", p1: [3, -5], p2: [3, 5], kind: "line" }] },
      { bodies: [stopper], points: [{ id: "P", p: [3, 0] }] },
      { bodies: [stopper], lines: [{ id: "S", p1: [2, 1], p2: [2, 5], kind: "segment" }] },
      { bodies: [stopper], lines: [{ id: "S", p1: [1, 1], p2: [1, 5], kind: "segment" }] },
    ];
    for (const o of others) {
      const r = run(scene({ g: 1, ...o }), 10);
      expect(r.events.map(brief)).toEqual([[2, "stop", "A", null, 0]]);
      expect(r.bodies.find((s) => s.id === "A")).toMatchObject({ x: 2, y: 0, vx: 0, vy: 0 });
    }
  });

  it("two discs braking head on stop touching, with no collision", () => {
    const r = run(scene({ g: 1, bodies: [stopper, body("B", { x: 6, y: 0, mu: 1, vx: -2 })] }), 10);
    expect(r.events.map(brief)).toEqual([
      [2, "stop", "A", null, 0],
      [2, "stop", "B", null, 0],
    ]);
  });
});

describe("parabolas and the ends of segments and rays", () => {
  // From (0, 3) with v = (1, 0) under gravity (0, -1): at t = 2 the centre is at (2, 1).
  const thrown = body("A", { x: 0, y: 3, vx: 1 });
  it("landing exactly on a segment's end bounces once, then falls past it", () => {
    const r = run(
      scene({
        gravity: [0, -1],
        bodies: [thrown],
        lines: [{ id: "S", p1: [-5, 0], p2: [2, 0], kind: "segment" }],
      }),
      20,
    );
    expect(r.events.map(brief)).toEqual([[2, "bodyLine", "A", "S", 4]]);
    expect(r.bodies[0]).toMatchObject({ x: 20, y: -125, vx: 1, vy: -16 });
  });

  it("landing exactly on a ray's origin bounces every 4 s along the ray", () => {
    const r = run(
      scene({
        gravity: [0, -1],
        bodies: [thrown],
        lines: [{ id: "R", p1: [2, 0], p2: [10, 0], kind: "ray" }],
      }),
      20,
    );
    expect(r.events.map(brief)).toEqual([2, 6, 10, 14, 18].map((t) => [t, "bodyLine", "A", "R", 4]));
    expect(r.bodies[0]).toMatchObject({ x: 20, y: 3, vx: 1, vy: 0 });
  });

  it("an apex exactly tangent to a segment's end or a point is a graze: no event", () => {
    // From (0, 0) with v = (1, 2): apex (2, 2) at t = 2, one radius below (2, 3).
    const up = body("A", { x: 0, y: 0, vx: 1, vy: 2 });
    for (const o of [
      { lines: [{ id: "S", p1: [2, 3], p2: [2, 10], kind: "segment" }] },
      { points: [{ id: "P", p: [2, 3] }] },
    ] as Partial<SceneSpec>[]) {
      const r = run(scene({ gravity: [0, -1], bodies: [up], ...o }), 20);
      expect(r.events).toEqual([]);
      expect(r.bodies[0]).toMatchObject({ x: 20, y: -160, vx: 1, vy: -18 });
    }
  });
});

describe("immovable bodies (m = Infinity) in motion", () => {
  it("against a disc, a line, a point and another immovable disc: defined, finite velocities", () => {
    const I = body("I", { x: 0, y: 0, m: Number.POSITIVE_INFINITY, vx: 1 });
    const disc = run(scene({ bodies: [I, body("f", { x: 5, y: 0.5 })] }), 10);
    expect(disc.events.map((e) => e.a + e.b)).toEqual(["If"]);
    expect(disc.bodies[0]).toMatchObject({ vx: 1, vy: 0 });
    // The finite disc takes twice the normal velocity: 2 (v.n) n, v.n = sqrt(15)/4.
    expect(disc.bodies[1]?.vx).toBeCloseTo(1.875, 14);
    expect(disc.bodies[1]?.vy).toBeCloseTo(Math.sqrt(15) / 8, 14);
    expect(disc.events[0]?.impulse).toBeCloseTo(Math.sqrt(15) / 2, 14);

    const wall = run(scene({ bodies: [I], lines: [{ id: "W", p1: [5, -5], p2: [5, 5], kind: "line" }] }), 10);
    expect(wall.events.map(brief)).toEqual([[4, "bodyLine", "I", "W", Number.POSITIVE_INFINITY]]);
    expect(wall.bodies[0]).toMatchObject({ x: -2, vx: -1, vy: 0 });

    const head = run(
      scene({ bodies: [I, body("J", { x: 5, y: 0, m: Number.POSITIVE_INFINITY, vx: -2 })] }),
      10,
    );
    expect(head.events.map(brief)).toEqual([[1, "bodyBody", "I", "J", Number.POSITIVE_INFINITY]]);
    expect(head.bodies.map((s) => [s.x, s.vx])).toEqual([
      [-17, -2],
      [12, 1],
    ]);
    for (const r of [disc, wall, head])
      for (const s of r.bodies) expect([s.x, s.y, s.vx, s.vy].every(Number.isFinite)).toBe(true);
  });
});
