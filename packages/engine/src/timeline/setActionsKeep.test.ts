/**
 * What Timeline.setActions keeps (edits.ts actionsOnCore): the history up to the first change of the
 * action list in applying order, compared by value. A change after the horizon cuts nothing; at
 * the horizon it joins the instant's action group unless events that group caused were computed;
 * a change of an applied action recomputes. Results as from scratch (setActionsSuffix.prop.test.ts
 * checks that on random scenes).
 */
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { coreOf, disc, fingerprint, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const INF = Number.POSITIVE_INFINITY;

/** Two touching discs at rest; at t = 1 a is pushed into b: they collide at that same instant. */
const TOUCHING: Action[] = [disc("a", 0, 0), disc("b", 2, 0)];
const PUSH: Action = { time: 1, type: "giveVelocity", id: "a", v: [1, 0] };
const PUSH_BACK: Action = { time: 1, type: "giveVelocity", id: "b", v: [-1, 0] };

function fromScratch(actions: readonly Action[], history: boolean, t: number): Timeline {
  const tl = Timeline.fromScene(scene([...actions], 0), { history });
  tl.prolongTo(t);
  return tl;
}

describe("setActions keeps the history up to the first change", () => {
  it("a change after the horizon cuts nothing: the log is the same entries, then goes on", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0, [1, 0]), disc("b", 10, 0)], 0));
    tl.prolongTo(20);
    const log = tl.eventRange(0, INF);
    const rewrites = coreOf(tl).rewrites;
    const late: Action = { time: 30, type: "giveVelocity", id: "a", v: [0, 1] };
    tl.setActions([...tl.toScene().actions, late]); // copies: compared by value
    expect(coreOf(tl).rewrites).toBe(rewrites);
    expect(tl.eventRange(0, log.length)).toStrictEqual(log);
    expect(tl.horizon).toBe(30);
    expect(fingerprint(tl)).toStrictEqual(fingerprint(fromScratch(tl.actions, true, 30)));
  });

  it("the same list, or one only reordered across times, changes nothing (listeners still told)", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0, [1, 0]), disc("b", 10, 0)], 0));
    tl.apply({ time: 5, type: "giveVelocity", id: "b", v: [0, 1] });
    tl.prolongTo(20);
    const before = fingerprint(tl);
    const rewrites = coreOf(tl).rewrites;
    let told = 0;
    tl.subscribe(() => told++);
    tl.setActions(tl.actions);
    const [a, b, kick] = tl.actions;
    tl.setActions([kick as Action, a as Action, b as Action]); // the times order them back
    expect([told, coreOf(tl).rewrites, tl.actions]).toStrictEqual([2, rewrites, [a, b, kick]]);
    expect(fingerprint(tl)).toStrictEqual(before);
  });

  it("at the horizon, an action joins the instant's group if nothing it caused was computed yet", () => {
    for (const history of [true, false]) {
      // computed up to its last action (no goal past it): the collision at 1 is not computed yet
      const tl = Timeline.fromScene(scene([...TOUCHING, PUSH], 0), { history });
      expect([tl.horizon, tl.counts().bodyBody]).toEqual([1, 0]);
      tl.setActions([...tl.actions, PUSH_BACK]);
      expect(tl.horizon).toBe(1);
      tl.prolongTo(3);
      const ref = fromScratch([...TOUCHING, PUSH, PUSH_BACK], history, 3);
      expect(tl.stateAt(3), `history ${history}`).toStrictEqual(ref.stateAt(3));
      expect(tl.counts()).toStrictEqual(ref.counts());
    }
  });

  it("at the horizon after events the group caused there, it is recomputed (it comes before them)", () => {
    for (const history of [true, false]) {
      const tl = fromScratch(TOUCHING, history, 0.5);
      tl.apply(PUSH); // computes the instant: the collision at 1 too
      expect([tl.horizon, tl.counts().bodyBody]).toEqual([1, 1]);
      tl.setActions([...tl.actions, PUSH_BACK]);
      tl.prolongTo(3);
      const ref = fromScratch([...TOUCHING, PUSH, PUSH_BACK], history, 3);
      // both pushed at once, they bounce apart: a goes back at -1, b on at 1
      expect(ref.stateAt(3).bodies.map((b) => b.vx)).toEqual([-1, 1]);
      expect(tl.stateAt(3), `history ${history}`).toStrictEqual(ref.stateAt(3));
      expect(tl.counts()).toStrictEqual(ref.counts());
    }
  });

  it("swapping two actions at one instant is a change there; so is a changed applied action", () => {
    const up: Action = { time: 1, type: "updateBody", id: "a", v: [0, 1] };
    const push: Action = { ...PUSH, v: [3, 0] };
    const tl = fromScratch([...TOUCHING, up, push], true, 4); // the push given last wins: a hits b
    const pushed = fingerprint(tl);
    tl.setActions([...TOUCHING, push, up]); // now a goes up
    expect(fingerprint(tl)).not.toStrictEqual(pushed);
    expect(fingerprint(tl)).toStrictEqual(fingerprint(fromScratch([...TOUCHING, push, up], true, 4)));
    const slower: Action = { ...up, v: [0, 2] };
    tl.setActions([...TOUCHING, push, slower]);
    expect(fingerprint(tl)).toStrictEqual(fingerprint(fromScratch([...TOUCHING, push, slower], true, 4)));
  });

  it("a refused action after the horizon changes nothing, the history kept included", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0, [1, 0])], 0));
    tl.prolongTo(5);
    const before = fingerprint(tl);
    expect(() => tl.setActions([...tl.actions, disc("b", 10, 0, [0, 0], 10)])).toThrow(
      'actions[1]: body "b" would overlap body "a" at time 10',
    );
    expect(fingerprint(tl)).toStrictEqual(before);
  });
});
