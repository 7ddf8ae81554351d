/**
 * Test support: random worlds on a lattice and random operations on them, for the property tests of
 * World.nextEventTime (sim/nextEventTime.prop.test.ts). A scene: discs centred in the cells of a
 * k × k lattice of unit squares (with or without friction, finite and infinite masses), a box of
 * segments, inner points, segments, rays and lines on the lattice lines (never inside a disc);
 * small worlds and worlds of 64+ bodies, where the grid is active. An operation: advance by events
 * or by time, addBody, updateBody (a kick), removeBody, addPoint, or a peek (the test's own).
 * `apply` runs one on a World and returns everything it showed as exact bits (eventDigest.ts), so
 * that two Worlds given the same operations can be compared bit for bit.
 */
import fc from "fast-check";
import { World } from "../src/sim/world.js";
import { bits, EventLog } from "./eventDigest.js";

const INF = Number.POSITIVE_INFINITY;
const num = (min: number, max: number) => fc.double({ min, max, noNaN: true, noDefaultInfinity: true });
const speed = fc.oneof(fc.constant(0), num(0.1, 3), num(-3, -0.1));

/** Discs centred in the cells of a k × k lattice of unit squares (radius < 0.5: no overlaps). */
const bodyArb = fc.record({
  cell: fc.nat(),
  r: num(0.05, 0.45),
  vx: speed,
  vy: speed,
  m: fc.oneof({ weight: 8, arbitrary: num(0.5, 5) }, { weight: 1, arbitrary: fc.constant(INF) }),
});
export const sceneArb = fc.record({
  bodies: fc.oneof(
    fc.array(bodyArb, { minLength: 1, maxLength: 12 }),
    fc.array(bodyArb, { minLength: 64, maxLength: 110 }),
  ),
  mu: fc.oneof(fc.constant(0), num(0.05, 0.5)),
  g: num(0.5, 10),
  /** Inner obstacles on the lattice lines (never inside a disc): [kind, lattice node]. */
  obstacles: fc.array(fc.tuple(fc.constantFrom("point", "segment", "ray", "line"), fc.nat()), {
    maxLength: 4,
  }),
});
export type Scene = typeof sceneArb extends fc.Arbitrary<infer T> ? T : never;

export const opArb = fc.oneof(
  {
    weight: 4,
    arbitrary: fc.record({ op: fc.constant("events" as const), k: fc.integer({ min: 1, max: 25 }) }),
  },
  { weight: 3, arbitrary: fc.record({ op: fc.constant("time" as const), dt: num(0, 2) }) },
  { weight: 5, arbitrary: fc.record({ op: fc.constant("peek" as const) }) },
  {
    weight: 2,
    arbitrary: fc.record({
      op: fc.constant("add" as const),
      cell: fc.nat(),
      r: num(0.05, 0.45),
      vx: speed,
      vy: speed,
    }),
  },
  {
    weight: 2,
    arbitrary: fc.record({ op: fc.constant("kick" as const), which: fc.nat(), vx: speed, vy: speed }),
  },
  { weight: 1, arbitrary: fc.record({ op: fc.constant("remove" as const), which: fc.nat() }) },
  { weight: 1, arbitrary: fc.record({ op: fc.constant("point" as const), node: fc.nat() }) },
);
export type Op = typeof opArb extends fc.Arbitrary<infer T> ? T : never;

/** Side of the lattice for a scene. */
export const sideOf = (p: Scene): number => Math.ceil(Math.sqrt(p.bodies.length * 1.5)) + 1;

/** The World of a scene: the box, the inner obstacles, then the discs (ids b000, b001, …). */
export function build(p: Scene): World {
  const k = sideOf(p);
  const w = new World({ g: p.g });
  w.addLine("wS", [0, 0], [k, 0], "segment");
  w.addLine("wE", [k, 0], [k, k], "segment");
  w.addLine("wN", [k, k], [0, k], "segment");
  w.addLine("wW", [0, k], [0, 0], "segment");
  p.obstacles.forEach(([kind, node], i) => {
    const x = 1 + (node % (k - 1));
    const y = 1 + (Math.floor(node / (k - 1)) % (k - 1));
    if (kind === "point") w.addPoint(`p${i}`, [x, y]);
    else w.addLine(`l${i}`, [x, y], kind === "segment" ? [x + 1, y] : [x, y + 1], kind);
  });
  const used = new Set<number>();
  p.bodies.forEach((b, i) => {
    let cell = b.cell % (k * k);
    while (used.has(cell)) cell = (cell + 1) % (k * k); // k * k > 1.5 n: a free cell exists
    used.add(cell);
    const still = b.m === INF;
    w.addBody(`b${String(i).padStart(3, "0")}`, {
      x: (cell % k) + 0.5,
      y: Math.floor(cell / k) + 0.5,
      r: b.r,
      m: b.m,
      mu: p.mu,
      vx: still ? 0 : b.vx,
      vy: still ? 0 : b.vy,
    });
  });
  return w;
}

/**
 * Run op on a world (k: the lattice's side; serial: names an added body or point); returns what it
 * showed as exact bits: the result or error, the events, and the time, counts and bodies after.
 */
export function apply(w: World, op: Op, serial: number, k: number): unknown {
  const events = new EventLog();
  let result: unknown = null;
  const ids = w.bodies().map((b) => b.id);
  try {
    if (op.op === "events") result = w.advance({ maxEvents: op.k }, (e) => events.push(e));
    else if (op.op === "time") result = w.advance({ untilTime: w.time + op.dt }, (e) => events.push(e));
    else if (op.op === "add") {
      const cell = op.cell % (k * k);
      w.addBody(`n${serial}`, {
        x: (cell % k) + 0.5,
        y: Math.floor(cell / k) + 0.5,
        r: op.r,
        m: 1,
        vx: op.vx,
        vy: op.vy,
      });
    } else if (op.op === "kick" && ids.length > 0)
      w.updateBody(ids[op.which % ids.length] as string, { vx: op.vx, vy: op.vy });
    else if (op.op === "remove" && ids.length > 0) w.removeBody(ids[op.which % ids.length] as string);
    else if (op.op === "point") w.addPoint(`q${serial}`, [op.node % k, Math.floor(op.node / k) % k]);
  } catch (e) {
    result = { error: String(e) };
  }
  return bits({
    result,
    events: events.summary(),
    time: w.time,
    counts: { ...w.counts },
    bodies: w.bodies(),
  });
}
