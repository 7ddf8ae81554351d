/**
 * Reads over long chains of delta keyframes (keyframeChain.ts, motionCursor.ts, path.ts): a scene
 * built one action per call at successive instants (discs thrown under friction, some pushed, some
 * removed and their ids added again) keeps a keyframe per instant, most of them deltas many deep.
 * Every read there is what a timeline without history (no keyframes at all: its states come from
 * the World, at the time it was computed up to) showed at that time, bit for bit: stateAt and
 * bodyArraysAt at every instant and between instants, read forwards (going on across deltas),
 * backwards (each read loads its keyframe) and in a shuffled order (the chain index switching
 * chains), path() evaluated at every instant; also after an edit in the past cut a chain (a branch
 * grows beside the index of the old one) and after forgetBefore cut one in the middle.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { positionAt } from "../physics/motion.js";
import type { Action } from "../scene/types.js";
import type { Keyframe } from "./keyframe.js";
import { coreOf, expectSameAsStateAt, seedFor } from "./testSupport.js";
import { Timeline } from "./timeline.js";
import type { SceneState } from "./types.js";

const DT = 0.01;
const SIDE = 12;

/** The actions of n instants, one per instant: a disc added on a lattice spot of its own, thrown;
 *  every 7th instant a push of the newest disc, every 11th the removal of the oldest, whose id is
 *  added again (at rest, on that instant's spot) 5 instants later. */
function instants(n: number): Action[] {
  let s = 7;
  const rand = () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 4294967296;
  };
  const live: string[] = [];
  const gone: string[] = [];
  return Array.from({ length: n }, (_, k): Action => {
    const time = k * DT;
    const spot = { x: (k % SIDE) * 4, y: Math.floor(k / SIDE) * 4, r: 1, m: 1 };
    if (k % 11 === 10 && live.length > 0) {
      const id = live.shift() as string;
      gone.push(id);
      return { time, type: "removeBody", id };
    }
    if (k % 11 === 4 && gone.length > 0) {
      const id = gone.shift() as string;
      live.push(id);
      return { time, type: "addBody", id, ...spot };
    }
    if (k % 7 === 6 && live.length > 0)
      return { time, type: "giveVelocity", id: live[live.length - 1] as string, v: [rand() - 0.5, rand()] };
    const angle = 2 * Math.PI * rand();
    const speed = 1 + 1.4 * rand();
    live.push(`d${k}`);
    const v: [number, number] = [speed * Math.cos(angle), speed * Math.sin(angle)];
    return { time, type: "addBody", id: `d${k}`, ...spot, mu: 0.2, v };
  });
}

/** Build `actions` one per call into a timeline with history and one without; the latter's states
 *  at every instant and halfway to the next (read from its World as it is computed). */
function build(actions: readonly Action[]): { tl: Timeline; times: number[]; seen: SceneState[] } {
  const tl = new Timeline({ g: 9.81 });
  const headless = new Timeline({ g: 9.81, history: false });
  const times: number[] = [];
  const seen: SceneState[] = [];
  actions.forEach((a, k) => {
    tl.apply(a);
    headless.apply(a);
    if (actions[k + 1]?.time === a.time) return; // (the instant's next action first)
    for (const t of [a.time, a.time + DT / 2]) {
      headless.prolongTo(t);
      times.push(t);
      seen.push(headless.stateAt(t));
    }
  });
  tl.prolongTo(times[times.length - 1] as number);
  return { tl, times, seen };
}

/** Depth of each keyframe in its chain (0: a full keyframe). */
function depths(tl: Timeline): number[] {
  return coreOf(tl).keyframes.map((kf: Keyframe) => {
    let d = 0;
    for (let k = kf; k.delta !== null; k = k.delta.prev) d++;
    return d;
  });
}

/** Expect every read of `tl` at times[k] (k in `order`) to be seen[k], states and arrays. */
function expectReads(tl: Timeline, times: number[], seen: SceneState[], order: readonly number[]): void {
  let into: ReturnType<Timeline["bodyArraysAt"]> | undefined;
  for (const k of order) {
    const s = tl.stateAt(times[k] as number);
    expect(s).toStrictEqual(seen[k]);
    into = tl.bodyArraysAt(times[k] as number, into);
    expectSameAsStateAt(into, s);
  }
}

/** Expect each body's path, evaluated at every time it covers, to be where stateAt puts it. */
function expectPaths(tl: Timeline, times: number[], seen: SceneState[]): void {
  const ids = new Set(seen.flatMap((s) => s.bodies.map((b) => b.id)));
  for (const id of ids) {
    const path = tl.path(id);
    times.forEach((t, k) => {
      const piece = path.find((p) => p.from <= t && t < p.until);
      const body = seen[k]?.bodies.find((b) => b.id === id);
      if (piece === undefined) return; // (not there, or at a piece's end: the next one covers it)
      const at = Math.min(t, piece.tStop);
      expect([
        positionAt(piece.t0, piece.x0, piece.vx, piece.ax, at),
        positionAt(piece.t0, piece.y0, piece.vy, piece.ay, at),
      ]).toStrictEqual([body?.x, body?.y]);
    });
  }
}

const order = (n: number) => Array.from({ length: n }, (_, k) => k);

describe("reads over a long chain of delta keyframes", () => {
  const actions = instants(400);
  const { tl, times, seen } = build(actions);

  it("keeps a keyframe per instant, most of them deltas, chains many deep", () => {
    const d = depths(tl);
    expect(d.length).toBeGreaterThanOrEqual(actions.length);
    expect(d.filter((x) => x > 0).length).toBeGreaterThan(0.9 * actions.length);
    expect(Math.max(...d)).toBeGreaterThan(64);
  });

  it("reads forwards, backwards and in any order what a timeline without history showed", () => {
    expectReads(tl, times, seen, order(times.length));
    expectReads(tl, times, seen, order(times.length).reverse());
    const seed = seedFor("chain reads in any order");
    fc.assert(
      fc.property(fc.array(fc.nat(times.length - 1), { minLength: 1, maxLength: 60 }), (ks) => {
        expectReads(tl, times, seen, ks);
      }),
      { seed, numRuns: 40 },
    );
  });

  it("gives paths that pass where stateAt puts each body", () => {
    expectPaths(tl, times, seen);
  });

  it("reads a chain an edit in the past cut, and the branch grown beside it, as building it afresh", () => {
    const edited = new Timeline({ g: 9.81 });
    edited.setActions(actions);
    edited.prolongTo(tl.horizon);
    expectReads(edited, times, seen, order(times.length).reverse()); // (every chain's index made)
    const id = edited.stateAt(150 * DT).bodies[0]?.id as string;
    const push: Action = { time: 150 * DT, type: "giveVelocity", id, v: [3, -2] };
    edited.apply(push);
    const fresh = build([...actions.slice(0, 151), push, ...actions.slice(151)]);
    fresh.times.forEach((t, k) => {
      expect(edited.stateAt(t)).toStrictEqual(fresh.seen[k]);
    });
    expectReads(edited, fresh.times, fresh.seen, order(fresh.times.length).reverse());
    expectPaths(edited, fresh.times, fresh.seen);
  });

  it("reads what is kept after forgetBefore cut a chain in the middle", () => {
    const cut = new Timeline({ g: 9.81 });
    for (const a of actions) cut.apply(a);
    cut.prolongTo(tl.horizon);
    const mid = depths(cut).findIndex((x, k) => x > 20 && k > 200);
    cut.forgetBefore((coreOf(cut).keyframes[mid] as Keyframe).time);
    const kept = order(times.length).filter((k) => (times[k] as number) >= cut.historyStart);
    expect(kept.length).toBeGreaterThan(100);
    expectReads(cut, times, seen, kept);
    expectReads(cut, times, seen, [...kept].reverse());
  });
});
