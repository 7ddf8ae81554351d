/**
 * Property tests of World.nextEventTime on random worlds (discs on a lattice, with or without
 * friction, finite and infinite masses, a box of segments, inner points, segments, rays and lines;
 * small worlds and worlds of 64+ bodies, where the grid is active and cell crossings come before
 * most events) under random interleavings of advance by events and by time, addBody, updateBody
 * (a kick), removeBody, addPoint and nextEventTime:
 * - a world that peeks stays bit for bit equal to a twin that never does: every event, every
 *   advance result, every error, `time`, `counts` and `bodies()` after each operation;
 * - each answer (or error) equals that of a copy advanced by one event.
 * Each property logs its seed (fixed by default, so CI is reproducible); explore others with FC_SEED=<n>.
 */
import fc from "fast-check";
import { afterAll, describe, expect, it, type MockInstance, vi } from "vitest";
import { Simulator } from "./simulator.js";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

const RUNS = Number(process.env.RUNS ?? 100);
function seedFor(name: string): number {
  // A fixed default keeps CI reproducible; set FC_SEED to explore others.
  const seed = Number(process.env.FC_SEED || process.env.SEED || 20261122); // FC_SEED, as every property test (SEED still works)
  console.log(`${name}: seed ${seed} (set FC_SEED to change)`);
  return seed;
}

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
const sceneArb = fc.record({
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
type Scene = typeof sceneArb extends fc.Arbitrary<infer T> ? T : never;

const opArb = fc.oneof(
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
type Op = typeof opArb extends fc.Arbitrary<infer T> ? T : never;

/** Side of the lattice for a scene. */
const sideOf = (p: Scene): number => Math.ceil(Math.sqrt(p.bodies.length * 1.5)) + 1;

function build(p: Scene): World {
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

/** Numbers as their exact bits (+0 and -0, NaN payloads all distinct). */
function bits(v: unknown): unknown {
  if (typeof v === "number") {
    const f = new Float64Array([v]);
    return `${new BigUint64Array(f.buffer)[0]?.toString(16)}`;
  }
  if (Array.isArray(v)) return v.map(bits);
  if (v && typeof v === "object")
    return Object.fromEntries(Object.entries(v).map(([key, x]) => [key, bits(x)]));
  return v;
}

/** Events kept whole for a readable diff; the rest are compared through a digest of their bits. */
const EVENTS_KEPT = 200;
const F64 = new Float64Array(1);
const U32 = new Uint32Array(F64.buffer);

/**
 * The events an advance reported: the first EVENTS_KEPT as copies, and how many there were with two
 * FNV-1a hashes of every field's bits (a scene that runs into a Zeno state reports millions of
 * events before the watch stops it: kept whole, their copies and comparison took a minute).
 */
class EventLog {
  readonly first: WorldEvent[] = [];
  count = 0;
  private h1 = 0x811c9dc5;
  private h2 = 0x01000193;
  push(e: WorldEvent): void {
    if (this.first.length < EVENTS_KEPT) this.first.push({ ...e });
    this.count++;
    for (const v of Object.values(e)) {
      if (typeof v === "number") {
        F64[0] = v;
        this.mix(U32[0] as number);
        this.mix(U32[1] as number);
      } else if (typeof v === "string") for (let i = 0; i < v.length; i++) this.mix(v.charCodeAt(i));
      else this.mix(0xffffffff);
    }
  }
  private mix(x: number): void {
    this.h1 = Math.imul(this.h1 ^ x, 0x01000193) >>> 0;
    this.h2 = Math.imul(this.h2 ^ x ^ (this.h1 >>> 7), 0x85ebca6b) >>> 0;
  }
  /** What two runs must agree on. */
  summary(): unknown {
    return { first: this.first, count: this.count, digest: [this.h1, this.h2] };
  }
}

/** Run op on a world; returns what it showed (result or error, events, and the state after). */
function apply(w: World, op: Op, serial: number, k: number): unknown {
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

/** What nextEventTime should answer: the time of the event a copy processes first (or its error). */
function expectedPeek(w: World): unknown {
  const c = w.clone();
  let t = INF;
  try {
    c.advance({ maxEvents: 1 }, (e) => {
      t = e.time;
    });
  } catch (e) {
    return { error: String(e) };
  }
  return t;
}

function peek(w: World): unknown {
  try {
    return w.nextEventTime();
  } catch (e) {
    return { error: String(e) };
  }
}

// Coverage: the internal work peeks did in place (crossings, stale predictions), counted across the
// runs. The spies are installed around each peek only: left on, they wrapped every call of every
// advance, and a scene that runs into a Zeno state (2.4 million events before the watch reports it,
// 4 s unspied) took 80 s under them (FC_SEED=424242).
type Spied = Record<string, (...a: unknown[]) => unknown>;
interface PeekSpies {
  cross: MockInstance;
  predict: MockInstance;
  clone: MockInstance;
}
function spyPeek(): PeekSpies {
  return {
    clone: vi.spyOn(World.prototype, "clone"),
    cross: vi.spyOn(Simulator.prototype as unknown as Spied, "processCrossing"),
    predict: vi.spyOn(Simulator.prototype as unknown as Spied, "predict"),
  };
}
afterAll(() => vi.restoreAllMocks());

describe("World.nextEventTime properties", () => {
  it("peeking changes nothing observable, and each answer is the time of the next event", () => {
    let crossings = 0;
    let repredictions = 0;
    let finite = 0;
    /** In-place peeks in which one body both crossed a cell and was re-predicted. */
    let both = 0;
    fc.assert(
      fc.property(
        sceneArb,
        fc.array(opArb, { minLength: 1, maxLength: 40, size: "max" }),
        fc.boolean(),
        (p, ops, peekAlways) => {
          const k = sideOf(p);
          const peeker = build(p);
          const twin = build(p);
          ops.forEach((op, i) => {
            if (op.op === "peek" || peekAlways) {
              const want = expectedPeek(peeker);
              const spies = spyPeek();
              let got: unknown;
              let calls: { cross: unknown[][]; predict: unknown[][]; clones: number };
              try {
                got = peek(peeker);
              } finally {
                // (restoring a spy forgets its calls)
                calls = {
                  cross: spies.cross.mock.calls.slice(),
                  predict: spies.predict.mock.calls.slice(),
                  clones: spies.clone.mock.calls.length,
                };
                for (const spy of Object.values(spies)) spy.mockRestore();
              }
              expect(bits(got)).toStrictEqual(bits(want));
              if (calls.clones === 0) {
                // In place (not the copy made while predictions are out of date).
                if (typeof got === "number" && got < INF) finite++;
                crossings += calls.cross.length;
                repredictions += calls.predict.length;
                const crossed = new Set(calls.cross.map((c) => c[0]));
                if (calls.predict.some((c) => crossed.has(c[0]))) both++;
              }
              expect(bits(peek(peeker))).toStrictEqual(bits(want)); // twice in a row: the same
            }
            if (op.op !== "peek") expect(apply(peeker, op, i, k)).toStrictEqual(apply(twin, op, i, k));
          });
          // The hidden state (predictions, grid) agrees too: the futures are the same.
          const tail: Op = { op: "events", k: 300 };
          expect(apply(peeker, tail, -1, k)).toStrictEqual(apply(twin, tail, -1, k));
        },
      ),
      { seed: seedFor("peek"), numRuns: RUNS, verbose: true },
    );
    console.log(
      `in-place peeks with a finite answer: ${finite}; in them: crossings ${crossings}, predictions ${repredictions}; one body crossing and re-predicted in ${both}`,
    );
    // The runs must have exercised the in-place work that is undone, or they prove little.
    expect(finite).toBeGreaterThan(RUNS);
    expect(crossings).toBeGreaterThan(RUNS);
    expect(repredictions).toBeGreaterThan(0);
    // Some seeds draw a disc crushed under friction (an immovable disc kicked into a wall): the Zeno
    // watch reports it only after its windows of 200,000 events have shrunk for long enough, 2.4
    // million events that this property runs twice (peeker and twin), 80 s under load for
    // FC_SEED=18003. The default seed takes 8 s.
  }, 300_000);
});
