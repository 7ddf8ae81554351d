/**
 * The chain caches belong to their Timeline (keyframeChain.ts ChainCache, TimelineCore.chains):
 * two Timelines read alternately each keep their chain indexes and their last keyframe's order
 * (nothing is made again: `made` counts what each cache had to build), a dropped Timeline's
 * keyframes are not kept reachable by any other's cache, an edit in the past grows a branch beside
 * the index of the chain it cut (which stays, as before), and forgetBefore empties the cache. Every
 * read here is also compared with a timeline built afresh, bit for bit.
 */
import { setFlagsFromString } from "node:v8";
import { runInNewContext } from "node:vm";
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { type Keyframe, keyframeAtOrBefore } from "./keyframe.js";
import { coreOf, expectSameKept } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const DT = 0.01;

/** n instants, one disc each, thrown under friction from a lattice spot of its own: a keyframe
 *  per instant, most of them deltas, in chains that grow longer as the scene grows. */
function thrown(n: number): Action[] {
  return Array.from({ length: n }, (_, k): Action => {
    const angle = 2.399963 * k; // (the golden angle: directions spread without a generator)
    const speed = 1 + (k % 5) * 0.3;
    const v: [number, number] = [speed * Math.cos(angle), speed * Math.sin(angle)];
    return {
      time: k * DT,
      type: "addBody",
      id: `d${k}`,
      x: (k % 12) * 4,
      y: Math.floor(k / 12) * 4,
      r: 1,
      m: 1,
      mu: 0.2,
      v,
    };
  });
}

/** Apply `actions` one per call (a keyframe per instant) and compute a little past the last. */
function build(actions: readonly Action[]): Timeline {
  const tl = new Timeline({ g: 9.81 });
  for (const a of actions) tl.apply(a);
  tl.prolongTo((actions[actions.length - 1] as Action).time + DT / 2);
  return tl;
}

/** A time in each of the last `count` chains of `tl` whose keyframe (the last at or before it) is
 *  a delta at depth 2 or more, so a read there asks the cache for its chain. */
function chainTimes(tl: Timeline, count: number): number[] {
  const kfs = coreOf(tl).keyframes;
  const times: number[] = [];
  for (let k = kfs.length - 1; k >= 0 && times.length < count; k--) {
    const kf = kfs[k] as Keyframe;
    const prev = kf.delta?.prev;
    if (prev?.delta === undefined || prev.delta === null) continue;
    if (times.some((t) => sameChain(kfs[keyframeAtOrBefore(kfs, t)] as Keyframe, kf))) continue;
    times.push(kf.time);
  }
  expect(times.length).toBe(count);
  for (const t of times) expect((kfs[keyframeAtOrBefore(kfs, t)] as Keyframe).delta).not.toBeNull();
  return times;
}

/** The full keyframe a keyframe's chain starts from. */
function chainStart(kf: Keyframe): Keyframe {
  let k = kf;
  while (k.delta !== null) k = k.delta.prev;
  return k;
}

const sameChain = (a: Keyframe, b: Keyframe) => chainStart(a) === chainStart(b);

describe("chain caches of a Timeline", () => {
  const actions = thrown(160);
  const fresh = build(actions);

  it("keeps each Timeline's indexes and last order when two are read alternately", () => {
    const a = build(actions);
    const b = build(actions);
    const ca = coreOf(a).chains;
    const cb = coreOf(b).chains;
    expect(ca).not.toBe(cb);
    // three chains each: six in all, more than one cache keeps (4), three fit in each
    const times = chainTimes(a, 3);
    expect(chainTimes(b, 3)).toStrictEqual(times);
    for (const t of times) {
      a.stateAt(t);
      b.stateAt(t);
    }
    const made = { a: { ...ca.made }, b: { ...cb.made } };
    expect(made.a.indexes).toBe(3);
    expect(made.b.indexes).toBe(3);
    for (let round = 0; round < 3; round++)
      for (const t of times) {
        const expected = fresh.stateAt(t);
        // the same keyframe twice in each: the second read of each is the last order kept
        for (let k = 0; k < 2; k++) {
          expect(a.stateAt(t)).toStrictEqual(expected);
          expect(b.stateAt(t)).toStrictEqual(expected);
        }
      }
    // no index made again; an order mapped once per change of keyframe (3 rounds × 3 times), not
    // once per read (2 reads each)
    expect(ca.made).toStrictEqual({ indexes: made.a.indexes, orders: made.a.orders + 9 });
    expect(cb.made).toStrictEqual({ indexes: made.b.indexes, orders: made.b.orders + 9 });
  });

  it("lets a dropped Timeline's keyframes be collected once read", async () => {
    setFlagsFromString("--expose-gc");
    const gc = runInNewContext("gc") as () => void;
    // a FinalizationRegistry, not a WeakRef: a WeakRef keeps its target alive until the end of the
    // job that made or read it, which a pause did not always reach here (about 1 run in 10)
    let collected = false;
    const registry = new FinalizationRegistry(() => {
      collected = true;
    });
    (() => {
      const tl = build(actions);
      const [t] = chainTimes(tl, 1) as [number];
      tl.stateAt(t);
      const kfs = coreOf(tl).keyframes;
      registry.register(kfs[keyframeAtOrBefore(kfs, t)] as Keyframe, "read");
    })();
    for (let k = 0; k < 10 && !collected; k++) {
      gc();
      await new Promise((done) => setTimeout(done, 0));
    }
    expect(collected).toBe(true);
  });

  it("holds none of another Timeline's keyframes", () => {
    const a = build(actions);
    const b = build(actions);
    const [t] = chainTimes(a, 1) as [number];
    a.stateAt(t);
    b.stateAt(t);
    const kfsA = coreOf(a).keyframes;
    const read = kfsA[keyframeAtOrBefore(kfsA, t)] as Keyframe;
    expect(coreOf(a).chains.holds(read)).toBe(true);
    expect(coreOf(b).chains.holds(read)).toBe(false);
    expect(kfsA.some((kf) => coreOf(b).chains.holds(kf))).toBe(false);
  });

  it("grows a branch beside the index of a chain an edit in the past cut, and keeps that index", () => {
    const tl = build(actions);
    const [late] = chainTimes(tl, 1) as [number];
    const kfs = coreOf(tl).keyframes;
    const old = kfs[keyframeAtOrBefore(kfs, late)] as Keyframe;
    // an instant in the middle of that chain: its keyframe and the chain before it stay
    const members: Keyframe[] = [];
    for (let k: Keyframe | undefined = old; k !== undefined; k = k.delta?.prev) members.push(k);
    const cutAt = (members[Math.floor(members.length / 2)] as Keyframe).time;
    expect(tl.stateAt(late)).toStrictEqual(fresh.stateAt(late));
    const chains = coreOf(tl).chains;
    const built = chains.made.indexes;
    const push: Action = { time: cutAt, type: "giveVelocity", id: "d0", v: [0.5, 0.5] };
    tl.apply(push);
    const edited = build([
      ...actions.filter((a) => a.time <= cutAt),
      push,
      ...actions.filter((a) => a.time > cutAt),
    ]);
    expect(tl.stateAt(late)).toStrictEqual(edited.stateAt(late));
    const now = coreOf(tl).keyframes;
    const grown = now[keyframeAtOrBefore(now, late)] as Keyframe;
    expect(grown).not.toBe(old);
    expect(sameChain(grown, old)).toBe(true); // a branch off the chain cut, not a chain of its own
    expect(chains.made.indexes).toBe(built + 1); // the branch's index
    expect(chains.holds(old)).toBe(true); // the index of the chain cut stays (an undo gives it back)
    const before = cutAt - DT;
    expect(tl.stateAt(before)).toStrictEqual(fresh.stateAt(before)); // (a keyframe both indexes hold)
    expect(chains.made.indexes).toBe(built + 1);
  });

  it("is emptied by forgetBefore, and reads what is kept as a timeline that never forgot", () => {
    const tl = build(actions);
    const times = chainTimes(tl, 2);
    for (const t of times) tl.stateAt(t);
    const core = coreOf(tl);
    const before = [...core.keyframes];
    expect(before.some((kf) => core.chains.holds(kf))).toBe(true);
    const [newest, older] = times as [number, number];
    tl.forgetBefore((older + newest) / 2);
    expect(tl.historyStart).toBeGreaterThan(older);
    expect(before.some((kf) => core.chains.holds(kf))).toBe(false);
    const built = core.chains.made.indexes;
    expect(tl.stateAt(newest)).toStrictEqual(fresh.stateAt(newest));
    expect(core.chains.made.indexes).toBe(built + 1);
    expectSameKept(tl, fresh, [newest, (tl.historyStart + tl.horizon) / 2]);
  });
});
