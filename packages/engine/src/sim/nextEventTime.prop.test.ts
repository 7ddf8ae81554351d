/**
 * Property tests of World.nextEventTime on random worlds (discs on a lattice, with or without
 * friction, finite and infinite masses, a box of segments, inner points, segments, rays and lines;
 * small worlds and worlds of 64+ bodies, where the grid is active and cell crossings come before
 * most events) under random interleavings of advance by events and by time, addBody, updateBody
 * (a kick), removeBody, addPoint and nextEventTime:
 * - a world that peeks stays bit for bit equal to a twin that never does: every event, every
 *   advance result, every error, `time`, `counts` and `bodies()` after each operation;
 * - each answer (or error) equals that of a copy advanced by one event.
 * The random worlds and operations: test/latticeWorld.ts; the comparison by bits: test/eventDigest.ts.
 * Each property logs its seed (fixed by default, so CI is reproducible); explore others with FC_SEED=<n>.
 */
import fc from "fast-check";
import { afterAll, describe, expect, it, type MockInstance, vi } from "vitest";
import { bits } from "../../test/eventDigest.js";
import { apply, build, type Op, opArb, sceneArb, sideOf } from "../../test/latticeWorld.js";
import { seedFor } from "../timeline/testSupport.js";
import { Simulator } from "./simulator.js";
import { World } from "./world.js";

const INF = Number.POSITIVE_INFINITY;

const RUNS = Number(process.env.RUNS ?? 100);
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
