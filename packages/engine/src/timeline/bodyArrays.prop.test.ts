/**
 * Property of Timeline.bodyArraysAt: on random scenes (friction, gravity or neither; a box of
 * segments, a ray, points; bodies removed, added and re-added over time; with and without history)
 * at random times and at the logged events' own times, the arrays hold stateAt(t).bodies bit for bit
 * (Object.is on every number, so -0 and 0 differ), whether they were written fresh or into the
 * previous result. The seed is printed (FC_SEED to explore others).
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import type { BodyArrays } from "../sim/bodyArrays.js";
import { ChapgameError, SimulationError } from "../sim/errors.js";
import { expectSameAsStateAt, num, seedFor, speed } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const RUNS = Number(process.env.RUNS ?? 40);
const fieldArb = fc.oneof(
  fc.record({ kind: fc.constant("friction" as const), mu: num(0.05, 1), g: num(0.5, 10) }),
  fc.record({ kind: fc.constant("gravity" as const), gx: speed, gy: speed }),
  fc.constant({ kind: "none" as const }),
);
const bodyArb = fc.record({
  r: num(0.3, 1.2),
  vx: speed,
  vy: speed,
  m: fc.oneof(
    { weight: 6, arbitrary: num(0.5, 5) },
    { weight: 1, arbitrary: fc.constant(Number.POSITIVE_INFINITY) },
  ),
});
/** A later edit at a fraction of the horizon: remove body `who`, add one (a new id, or a removed
 *  one again) at (x, y), or strike body `who`. Refused ones (an overlap, no such body) are skipped. */
const editArb = fc.record({
  kind: fc.constantFrom("remove", "add", "readd", "give"),
  frac: num(0.01, 0.95),
  who: fc.nat(),
  x: num(2, 18),
  y: num(2, 18),
  v: fc.tuple(speed, speed),
});
const caseArb = fc.record({
  bodies: fc.array(bodyArb, { minLength: 1, maxLength: 10 }),
  field: fieldArb,
  edits: fc.array(editArb, { maxLength: 5 }),
  horizon: num(0.5, 4),
  history: fc.boolean(),
  fracs: fc.array(num(0, 1), { minLength: 1, maxLength: 6 }),
});

type Case = typeof caseArb extends fc.Arbitrary<infer T> ? T : never;

/** The case's timeline, computed to its horizon (or to a Zeno state, which the reads then end at). */
function build(c: Case): Timeline {
  const f = c.field;
  const mu = f.kind === "friction" ? f.mu : 0;
  const tl = new Timeline({
    g: f.kind === "friction" ? f.g : 0,
    gravity: f.kind === "gravity" ? [f.gx, f.gy] : [0, 0],
    history: c.history,
  });
  const at0: Action[] = [
    { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
    { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 20], kind: "segment" },
    { time: 0, type: "addLine", id: "n", p1: [20, 20], p2: [0, 20], kind: "segment" },
    { time: 0, type: "addLine", id: "w", p1: [0, 20], p2: [0, 0], kind: "segment" },
    { time: 0, type: "addLine", id: "ray", p1: [10, 10.5], p2: [11, 10.5], kind: "ray" },
    { time: 0, type: "addPoint", id: "pin", p: [18.5, 18.5] },
  ];
  c.bodies.forEach((b, i) => {
    at0.push({
      time: 0,
      type: "addBody",
      id: `b${i}`,
      x: 2.5 + 5 * (i % 4),
      y: 2.5 + 5 * Math.floor(i / 4),
      r: b.r,
      m: b.m,
      mu,
      v: b.m === Number.POSITIVE_INFINITY ? [0, 0] : [b.vx, b.vy],
    });
  });
  for (const a of at0) tl.apply(a);
  const n = c.bodies.length;
  // in time order: a timeline without history refuses an action before its horizon
  const edits = [...c.edits].sort((p, q) => p.frac - q.frac);
  for (const [k, e] of edits.entries()) {
    const time = e.frac * c.horizon;
    const id = e.kind === "add" ? `new${k}` : `b${e.who % n}`;
    const action: Action =
      e.kind === "remove"
        ? { time, type: "removeBody", id }
        : e.kind === "give"
          ? { time, type: "giveVelocity", id, v: e.v }
          : { time, type: "addBody", id, x: e.x, y: e.y, r: 0.5, m: 1, mu, v: e.v };
    try {
      if (!c.history) tl.prolongTo(time);
      tl.apply(action);
    } catch (error) {
      // refused (an overlap, no such body, a Zeno state on the way): the timeline is unchanged
      if (!(error instanceof ChapgameError || error instanceof SimulationError)) throw error;
    }
  }
  try {
    tl.prolongTo(c.horizon);
  } catch (e) {
    if (!(e instanceof SimulationError)) throw e;
  }
  return tl;
}

/** Read `times` in this order with bodyArraysAt, fresh and into the last result, against stateAt. */
function expectReadsMatch(tl: Timeline, times: readonly number[], into?: BodyArrays): number {
  let last = into;
  for (const t of times) {
    const s = tl.stateAt(t);
    expectSameAsStateAt(tl.bodyArraysAt(t), s);
    last = tl.bodyArraysAt(t, last);
    expectSameAsStateAt(last, s);
  }
  return times.length;
}

/** Times from `from` to `to` in `steps` equal steps (a playback: each read goes on from the last). */
const playback = (from: number, to: number, steps: number) =>
  Array.from({ length: steps + 1 }, (_, k) => Math.min(to, from + ((to - from) * k) / steps));

describe("Timeline.bodyArraysAt", () => {
  it("equals stateAt(t).bodies bit for bit, fresh or written into the previous result, in any order of times", () => {
    let read = 0;
    fc.assert(
      fc.property(caseArb, (c) => {
        const tl = build(c);
        const h = tl.horizon;
        const from = c.history ? 0 : tl.lastLoggedTime();
        const times = [from, h, ...c.fracs.map((f) => from + f * (h - from))];
        // the logged instants themselves, in order, where several events may share a time
        if (c.history) times.push(...tl.eventsBetween(0, h).map((e) => e.time));
        times.push(...playback(from, h, 25));
        read += expectReadsMatch(tl, times);
      }),
      { seed: seedFor("bodyArraysAt"), numRuns: RUNS, verbose: true },
    );
    expect(read).toBeGreaterThan(RUNS * 30);
  });

  it("still equals stateAt after the history changes between reads (prolonged, an edit in the past, undone, its start forgotten)", () => {
    let read = 0;
    fc.assert(
      fc.property(caseArb, num(0.05, 0.95), fc.tuple(speed, speed), (c, frac, v) => {
        const tl = build({ ...c, history: true });
        const h = tl.horizon;
        const playAll = () => playback(tl.historyStart, tl.horizon, 12);
        read += expectReadsMatch(tl, playback(0, h, 12));
        const original = tl.actions;
        try {
          tl.prolongTo(h + 1); // appended records and keyframes: the last read's replay goes on
          read += expectReadsMatch(tl, playAll());
          const id = tl.stateAt(frac * h).bodies[0]?.id ?? "b0";
          tl.apply({ time: frac * h, type: "giveVelocity", id, v }); // cut and recomputed
          read += expectReadsMatch(tl, playAll());
          tl.setActions(original); // and undone
          read += expectReadsMatch(tl, playAll());
        } catch (e) {
          if (!(e instanceof ChapgameError || e instanceof SimulationError)) throw e;
        }
        tl.forgetBefore(frac * tl.horizon); // record and keyframe numbers move
        read += expectReadsMatch(tl, [tl.horizon, ...playAll()]);
      }),
      { seed: seedFor("bodyArraysAt after changes"), numRuns: RUNS, verbose: true },
    );
    expect(read).toBeGreaterThan(RUNS * 40);
  });
});
