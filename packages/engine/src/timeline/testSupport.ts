/**
 * Helpers of the timeline tests (not built, not published): small scenes, a fingerprint of
 * everything a timeline shows, for "nothing changed" checks, and the comparison of a timeline whose
 * start was forgotten with a twin that never forgot.
 */
import fc from "fast-check";
import { expect } from "vitest";
import type { Action, SceneFile } from "../scene/types.js";
import { ARRAY_FIELDS, type BodyArrays } from "../sim/bodyArrays.js";
import type { BodyState } from "../sim/types.js";
import type { TimelineCore } from "./core.js";
import type { Keyframe } from "./keyframe.js";
import { Timeline } from "./timeline.js";
import type { SceneState } from "./types.js";

export const scene = (actions: Action[], g = 9.81): SceneFile => ({
  format: "chapgame",
  version: 1,
  g,
  gravity: [0, 0],
  actions,
});

/** A disc of radius 1 and mass 1 without friction. */
export const disc = (id: string, x: number, y: number, v: [number, number] = [0, 0], time = 0): Action => ({
  time,
  type: "addBody",
  id,
  x,
  y,
  r: 1,
  m: 1,
  mu: 0,
  v,
});

/** Everything observable about a timeline, for "nothing changed" checks. */
export function fingerprint(tl: Timeline): unknown {
  const times = [0, tl.horizon / 3, tl.horizon / 2, tl.horizon];
  return {
    scene: tl.toScene(),
    horizon: tl.horizon,
    counts: tl.counts(),
    log: tl.eventsBetween(0, tl.horizon),
    states: times.map((t) => tl.stateAt(t)),
    bytes: tl.historyBytes(),
  };
}

/** The README's example: a light disc between a wall and a heavy one, 31 collisions up to t = 20. */
export function wallAndHeavyDisc(): Timeline {
  const tl = new Timeline({ g: 0 });
  tl.apply({ time: 0, type: "addLine", id: "wall", p1: [0, -10], p2: [0, 10], kind: "line" });
  tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1 });
  tl.apply({ time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 100, v: [-1, 0] });
  tl.prolong({ time: 20 });
  return tl;
}

/** Expect `a` (bodyArraysAt, World.bodyArrays) to hold exactly `time` and `bodies` (stateAt,
 *  World.bodies): ids, order, every number's bits (Object.is: -0 and 0 differ), and arrays exactly
 *  `count` long. */
export function expectSameBodies(a: BodyArrays, time: number, bodies: readonly BodyState[]): void {
  expect(Object.is(a.time, time)).toBe(true);
  expect(a.count).toBe(bodies.length);
  expect([...a.ids]).toStrictEqual(bodies.map((b) => b.id));
  for (const f of ARRAY_FIELDS) {
    expect(a[f].length).toBe(a.count);
    const differing = bodies.findIndex((b, k) => !Object.is(a[f][k], b[f]));
    expect(differing, `${f}[${differing}] at t = ${time}`).toBe(-1);
  }
}

/** expectSameBodies with stateAt's result. */
export function expectSameAsStateAt(a: BodyArrays, s: SceneState): void {
  expectSameBodies(a, s.time, s.bodies);
}

/** The core behind a timeline (tests look at its storage). */
export function coreOf(tl: Timeline): TimelineCore {
  return (tl as unknown as { core: TimelineCore }).core;
}

/**
 * Expect `tl` (whose start may be forgotten) to show what `twin` (the same scene and edits, nothing
 * forgotten) shows from tl.historyStart on, bit for bit: states at `times` (and at the start and the
 * horizon), the log from firstEvent on (by index and by time), the event lookups, totals and scene.
 */
export function expectSameKept(tl: Timeline, twin: Timeline, times: readonly number[] = []): void {
  const start = tl.historyStart;
  const h = tl.horizon;
  expect([h, tl.eventCount, tl.counts(), tl.toScene(), tl.actions]).toStrictEqual([
    twin.horizon,
    twin.eventCount,
    twin.counts(),
    twin.toScene(),
    twin.actions,
  ]);
  for (const t of [start, ...times, h]) {
    expect(tl.stateAt(t)).toStrictEqual(twin.stateAt(t));
    expect(tl.nextEventTime(t)).toBe(twin.nextEventTime(t));
    const prev = tl.prevEventTime(t);
    if (prev === null) expect(twin.prevEventTime(t) ?? start).toBeLessThanOrEqual(start);
    else expect(prev).toBe(twin.prevEventTime(t));
  }
  const first = tl.firstEvent;
  expect(tl.eventRange(first, Number.POSITIVE_INFINITY)).toStrictEqual(
    twin.eventRange(first, Number.POSITIVE_INFINITY),
  );
  // from the start by time: the twin's entries at the start logged before the cut are not kept
  const kept = tl.eventsBetween(start, h);
  const all = twin.eventsBetween(start, h);
  const skipped = all.slice(0, all.length - kept.length);
  expect(skipped.every((e) => e.time === start)).toBe(true);
  expect(kept).toStrictEqual(all.slice(skipped.length));
}

/** A property's fast-check seed, printed with `name` (`fixed` by default so CI is reproducible; set
 *  FC_SEED to explore others; SEED still works). */
export function seedFor(name: string, fixed = 20261122): number {
  const seed = Number(process.env.FC_SEED || process.env.SEED || fixed);
  console.log(`${name}: seed ${seed} (set FC_SEED to change)`);
  return seed;
}

/** A finite double in [min, max]. */
export const num = (min: number, max: number) =>
  fc.double({ min, max, noNaN: true, noDefaultInfinity: true });

/** A velocity component: 0 or 0.1…5 in size (not 1e-134: such a disc reaches a wall at t ~ 1e135,
 *  where time has no resolution left; that is outside what these properties are about). */
export const speed = fc.oneof(fc.constant(0), num(0.1, 5), num(-5, -0.1));

/**
 * What a Timeline's core holds besides the World: where it stands, its goals, keyframes and restart
 * points, its flags and counters, and the numbers of its live bodies, lines and points (the maps by
 * content: their order means nothing). Two timelines that took the same edits hold the same.
 */
export function coreInternals(tl: Timeline): unknown {
  const c = coreOf(tl);
  const k = (kf: Keyframe | null) =>
    kf === null ? null : [kf.time, kf.record, kf.actionCount, kf.world !== undefined];
  return {
    keyframes: c.rawKeyframes.map(k),
    owed: c.owed,
    spare: k(c.spare),
    goals: c.goals,
    dormant: c.dormant,
    flags: [c.atTimeLimit, c.groupOpen, c.idle, c.settled, c.eventAfterActions, c.applied],
    times: [c.lastLogged, c.lastActionTime, c.eventTotal],
    numbers: [c.live, c.lineNums, c.pointNums].map((m) => [...m].sort()),
  };
}

/**
 * A frictionless disc pushing a braking one (g = 0.5 for the scene): their collisions and stops
 * converge geometrically to t ≈ 52.249, a Zeno state the exact model cannot continue (found by the
 * slices property, seed 7). The two addBody actions at time 0.
 */
export const CONVERGING_PAIR: readonly Action[] = [
  { time: 0, type: "addBody", id: "b0", x: 3, y: 3, r: 0.3, m: 0.7401641156608975, mu: 0, v: [0.1, 0] },
  { time: 0, type: "addBody", id: "b1", x: 7, y: 3, r: 0.3, m: 0.5, mu: 0.05 },
];
