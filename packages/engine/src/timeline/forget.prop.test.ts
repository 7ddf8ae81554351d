/**
 * Property tests of Timeline.forgetBefore on random scenes with random actions: forgetting at random
 * times, then reading any time from the kept start on, and editing there, gives exactly what a twin
 * that never forgot gives; reads and edits before the start are refused and change nothing; the
 * memory drops. Small boxes (a keyframe after each action) and gases (keyframes between actions).
 * Each property logs its seed (fixed by default, so CI is reproducible); explore others with
 * FC_SEED=<n>.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { Action, SceneFile, Vec2 } from "../scene/types.js";
import { ChapgameError } from "../sim/errors.js";
import { coreOf, disc, expectSameKept, num, scene, seedFor, speed } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const RUNS = Number(process.env.RUNS ?? 25);

const vec: fc.Arbitrary<Vec2> = fc.tuple(speed, speed);
/** A kick: a fraction of the horizon, which disc (modulo their number), the new velocity. */
const kick = fc.record({ at: num(0, 1), who: fc.nat(), v: vec });

const H = 10;
const BOX: Action[] = [
  { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
  { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 20], kind: "segment" },
  { time: 0, type: "addLine", id: "n", p1: [20, 20], p2: [0, 20], kind: "segment" },
  { time: 0, type: "addLine", id: "w", p1: [0, 20], p2: [0, 0], kind: "segment" },
];

/** Discs on a grid 4 apart in a 20 × 20 box (no friction: they keep colliding), kicked at times. */
function boxScene(vs: Vec2[], kicks: { at: number; who: number; v: Vec2 }[]): SceneFile {
  const discs = vs.map((v, i) => disc(`d${i}`, 2 + (i % 4) * 4, 2 + Math.floor(i / 4) * 4, [v[0], v[1]]));
  const kicked = kicks.map(
    (k): Action => ({ time: k.at * H, type: "giveVelocity", id: `d${k.who % vs.length}`, v: k.v }),
  );
  return scene([...BOX, ...discs, ...kicked], 0);
}

/** The gas with a few kicks (keyframes every few hundred events, between the actions). */
function gasScene(n: number, seed: number, kicks: { at: number; who: number; v: Vec2 }[]): SceneFile {
  const s = dilutedGas({ n, packing: 0.15, seed });
  const ids = s.actions.flatMap((a) => (a.type === "addBody" ? [a.id] : []));
  const kicked = kicks.map(
    (k): Action => ({ time: k.at * 2, type: "giveVelocity", id: ids[k.who % ids.length] as string, v: k.v }),
  );
  return { ...s, actions: [...s.actions, ...kicked] };
}

/** What the timeline shows from its kept start on (for "nothing changed"). */
function kept(tl: Timeline): unknown {
  const s = tl.historyStart;
  return [
    tl.getSnapshot(),
    s,
    tl.firstEvent,
    tl.eventCount,
    tl.toScene(),
    tl.eventRange(tl.firstEvent, Number.POSITIVE_INFINITY),
    tl.stateAt(s),
    tl.stateAt(tl.horizon),
  ];
}

/** Run `f` on both timelines: both succeed, or both throw the same error. */
function both(tl: Timeline, twin: Timeline, f: (t: Timeline) => void): void {
  let mine: unknown = null;
  let theirs: unknown = null;
  try {
    f(twin);
  } catch (e) {
    theirs = e;
  }
  try {
    f(tl);
  } catch (e) {
    mine = e;
  }
  expect(mine === null ? null : String(mine)).toBe(theirs === null ? null : String(theirs));
}

/**
 * The property: forget at `cuts` (fractions of the horizon, each from the last start on), compare;
 * an edit at `edit` (a fraction of what is after the start), compare; undo it, compare; an edit and
 * a read before the start refused with nothing changed.
 */
function check(
  make: () => Timeline,
  cuts: number[],
  reads: number[],
  edit: { at: number; who: number; v: Vec2 },
): boolean {
  const tl = make();
  const twin = make();
  const h = tl.horizon;
  const records = coreOf(tl).records.length;
  const keyframes = coreOf(tl).keyframes.length;
  for (const f of cuts) {
    const t = tl.historyStart + f * (h - tl.historyStart);
    const start = tl.forgetBefore(t);
    expect(start).toBe(tl.historyStart);
    expect(start).toBeLessThanOrEqual(t);
    // the last keyframe at or before t: no keyframe of the twin lies in (start, t]
    expect(coreOf(twin).keyframes.some((k) => k.time > start && k.time <= t)).toBe(false);
  }
  const start = tl.historyStart;
  const at = (f: number) => start + f * (h - start);
  expectSameKept(tl, twin, reads.map(at));
  // the memory went: what was dropped is what was before the cut
  const c = coreOf(tl);
  expect(c.records.length).toBe(records - tl.firstEvent);
  expect(c.keyframes.length).toBe(
    keyframes - coreOf(twin).keyframes.filter((k) => k.record < tl.firstEvent).length,
  );
  // an edit strictly after the start, then its undo
  const ids = tl.stateAt(at(edit.at)).bodies.map((b) => b.id);
  const time = at(edit.at) === start ? h : at(edit.at);
  const action: Action = { time, type: "giveVelocity", id: ids[edit.who % ids.length] as string, v: edit.v };
  const list = tl.toScene().actions;
  both(tl, twin, (x) => x.apply(action));
  expectSameKept(tl, twin, reads.map(at));
  both(tl, twin, (x) => x.setActions(list));
  expectSameKept(tl, twin, reads.map(at));
  expect(tl.historyStart).toBe(start);
  if (start === 0) return false;
  // before the start: refused, nothing changed
  const before = kept(tl);
  const early = start * Math.min(edit.at, 0.5); // < start, also when start is subnormal
  expect(() => tl.apply({ ...action, time: early })).toThrow(ChapgameError);
  expect(() => tl.setActions(list.filter((a) => a.time !== 0 || a.type !== "addLine"))).toThrow(
    ChapgameError,
  );
  expect(() => tl.stateAt(early)).toThrow(RangeError);
  expect(() => tl.eventsBetween(early, h)).toThrow(RangeError);
  expect(() => tl.nextEventTime(early)).toThrow(RangeError);
  if (tl.firstEvent > 0) expect(() => tl.event(tl.firstEvent - 1)).toThrow(/was forgotten/);
  expect(kept(tl)).toStrictEqual(before);
  return true;
}

describe("Timeline.forgetBefore on random scenes", () => {
  it("a box of discs kicked at random times: the kept history is the twin's, bit for bit", () => {
    let cut = 0;
    fc.assert(
      fc.property(
        fc.array(vec, { minLength: 2, maxLength: 12 }),
        fc.array(kick, { maxLength: 8 }),
        fc.array(num(0, 1), { minLength: 1, maxLength: 3 }),
        fc.array(num(0, 1), { maxLength: 4 }),
        kick,
        (vs, kicks, cuts, reads, edit) => {
          const s = boxScene(vs, kicks);
          cut += +check(
            () => {
              const tl = Timeline.fromScene(s);
              tl.prolongTo(H);
              return tl;
            },
            cuts,
            reads,
            edit,
          );
        },
      ),
      { seed: seedFor("forget box"), numRuns: RUNS },
    );
    // most runs must cut after the start (a kick before the cut, or the gas's keyframes)
    expect(cut).toBeGreaterThanOrEqual(RUNS / 3);
  });

  it("a gas (keyframes between actions): the kept history is the twin's, bit for bit", () => {
    const runs = Math.max(1, Math.round(RUNS / 4));
    let cut = 0;
    fc.assert(
      fc.property(
        fc.integer({ min: 30, max: 80 }),
        fc.integer({ min: 1, max: 1000 }),
        fc.array(kick, { maxLength: 4 }),
        // past the first keyframe (about a quarter of the 4,000 events) in most runs: fast-check
        // favours the ends of a range, and cuts at 0 forgot nothing in 4 of 5 runs (seed 18002)
        fc.array(num(0.35, 1), { minLength: 1, maxLength: 2 }),
        fc.array(num(0, 1), { maxLength: 3 }),
        kick,
        (n, gasSeed, kicks, cuts, reads, edit) => {
          const s = gasScene(n, gasSeed, kicks);
          cut += +check(
            () => {
              const tl = Timeline.fromScene(s);
              tl.prolong({ events: 4000 });
              return tl;
            },
            cuts,
            reads,
            edit,
          );
        },
      ),
      { seed: seedFor("forget gas"), numRuns: runs },
    );
    expect(cut).toBeGreaterThanOrEqual(runs / 3);
  });
});
