/**
 * Property: whatever point a timeline was left at (after applies at one instant or at later ones,
 * with or without untils, prolongs by time, by events or in slices) and with or without history or
 * compute, an apply refused there (by its checks, or at a later instant after computing up to it,
 * which undoReplay.ts undoes by recomputing the World) leaves it exactly as a twin that was never
 * given it: the same observable history and internals now, and the same after the next edits.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { coreInternals, disc, fingerprint, seedFor } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const BOX: Action[] = [
  { time: 0, type: "addLine", id: "L", p1: [-10, -10], p2: [-10, 10], kind: "line" },
  { time: 0, type: "addLine", id: "R", p1: [10, -10], p2: [10, 10], kind: "line" },
  { time: 0, type: "addLine", id: "B", p1: [-10, -10], p2: [10, -10], kind: "line" },
  { time: 0, type: "addLine", id: "T", p1: [-10, 10], p2: [10, 10], kind: "line" },
];

type Op =
  | { kind: "add"; x: number; y: number; v: [number, number]; dt: number; until: number | null }
  | { kind: "push"; who: number; v: [number, number]; dt: number; until: number | null }
  | { kind: "prolong"; time: number | null; events: number | null }
  | { kind: "slice"; events: number; budget: number }
  // refused: an id already taken, at a later instant (the timeline computes up to it first)
  | { kind: "twice"; who: number; dt: number };

// (quarters and halves: fast-check's doubles favour tiny speeds, which the magnitude checks refuse)
const quarter = (lo: number, hi: number) => fc.integer({ min: lo * 4, max: hi * 4 }).map((k) => k / 4);
const vel = fc.tuple(quarter(-3, 3), quarter(-3, 3));
const dtArb = fc.constantFrom(0, 0, 0.1, 0.5, 1.25);
const untilArb = fc.option(fc.constantFrom(0.2, 1, 3), { nil: null });
const opArb: fc.Arbitrary<Op> = fc.oneof(
  fc.record({
    kind: fc.constant("add" as const),
    x: quarter(-9, 9),
    y: quarter(-9, 9),
    v: vel,
    dt: dtArb,
    until: untilArb,
  }),
  fc.record({ kind: fc.constant("push" as const), who: fc.nat(20), v: vel, dt: dtArb, until: untilArb }),
  fc.record({
    kind: fc.constant("prolong" as const),
    time: fc.option(fc.constantFrom(0.3, 1, 2.5), { nil: null }),
    events: fc.option(fc.integer({ min: 1, max: 40 }), { nil: null }),
  }),
  fc.record({
    kind: fc.constant("slice" as const),
    events: fc.integer({ min: 1, max: 60 }),
    budget: fc.integer({ min: 1, max: 7 }),
  }),
  fc.record({ kind: fc.constant("twice" as const), who: fc.nat(20), dt: fc.constantFrom(0.1, 0.5, 2) }),
);

/** Everything observable, then the internals (after the reads: run() reads the timeline it edits,
 *  which takes a keyframe owed, and the twin is not given the refused edits). */
function seen(tl: Timeline): unknown {
  const shown = tl.history
    ? fingerprint(tl)
    : { scene: tl.toScene(), horizon: tl.horizon, counts: tl.counts(), state: tl.stateAt(tl.horizon) };
  return { shown, inner: coreInternals(tl) };
}

/** Runs op on a timeline (reading its state at the horizon first), or throws as the timeline does. */
function run(tl: Timeline, op: Op, n: number): void {
  const h = tl.horizon;
  const ids = tl.stateAt(h).bodies.map((b) => b.id);
  const until = (u: number | null) => (u === null ? {} : { until: { time: u } });
  if (op.kind === "add")
    tl.apply({ ...disc(`d${n}`, op.x, op.y, op.v, h + op.dt), r: 0.5, ...until(op.until) } as Action);
  else if (op.kind === "push" && ids.length > 0)
    tl.apply({
      time: h + op.dt,
      type: "giveVelocity",
      id: ids[op.who % ids.length] as string,
      v: op.v,
      ...until(op.until),
    });
  else if (op.kind === "prolong") {
    const u: { time?: number; events?: number } = {};
    if (op.time !== null) u.time = op.time;
    if (op.events !== null) u.events = op.events;
    if (u.time === undefined && u.events === undefined) u.time = 1;
    tl.prolong(u);
  } else if (op.kind === "slice") {
    for (let k = 0; k < 3; k++) if (tl.prolongSlice({ events: op.events }, op.budget).done) break;
  } else if (op.kind === "twice" && ids.length > 0)
    tl.apply({ ...disc(ids[op.who % ids.length] as string, 0, 0, [0, 0], h + op.dt), r: 0.5 } as Action);
}

describe("a refused apply after any sequence of edits and prolongs changes nothing", () => {
  it("equals a twin that was never given the refused ones, bit for bit", () => {
    fc.assert(
      fc.property(
        fc.boolean(),
        fc.boolean(),
        fc.array(opArb, { minLength: 1, maxLength: 18 }),
        (history, compute, ops) => {
          const make = () => {
            const tl = new Timeline({ g: 0, history, compute });
            for (const a of BOX) tl.apply(a);
            return tl;
          };
          const tl = make();
          const twin = make();
          let refusals = 0;
          for (const [n, op] of ops.entries()) {
            const thrown = (t: Timeline) => {
              try {
                run(t, op, n);
                return false;
              } catch {
                return true;
              }
            };
            const refused = thrown(tl);
            // a prolong that meets a Zeno state keeps what it computed: the twin computes it too
            if (op.kind === "prolong" || op.kind === "slice") expect(thrown(twin)).toBe(refused);
            else if (refused) {
              refusals++;
              expect(seen(tl)).toStrictEqual(seen(twin));
            } else run(twin, op, n);
          }
          expect(seen(tl)).toStrictEqual(seen(twin));
          // and they go on alike
          for (const t of [tl, twin]) t.prolong({ time: 2 });
          expect(seen(tl)).toStrictEqual(seen(twin));
          return refusals >= 0;
        },
      ),
      { seed: seedFor("refused apply"), numRuns: 150 },
    );
  });
});
