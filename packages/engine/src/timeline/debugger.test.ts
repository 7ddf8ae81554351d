/**
 * A time-travel debugger built on the Timeline (not through the editor): reading states at any
 * time, walking the log, telling what an action entry did, and driving the computation in slices.
 * Found in a user review; each test says what happened before the fix.
 */
import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import type { Action } from "../scene/types.js";
import { SimulationError } from "../sim/errors.js";
import { CONVERGING_PAIR, wallAndHeavyDisc } from "./testSupport.js";
import { Timeline } from "./timeline.js";

describe("Timeline as a debugger's back end", () => {
  it("stateAt refuses a time that is not a number (null gave the state at 0, '3' a state whose time was a string)", () => {
    const tl = wallAndHeavyDisc();
    // each named as every refusal names a value (an array of one number read as "got 1" before)
    const named: [unknown, string][] = [
      [null, "null"],
      ["3", 'the string "3"'],
      [undefined, "undefined"],
      [Number.NaN, "NaN"],
      [[1], "an array of 1"],
    ];
    for (const [t, got] of named)
      expect(() => tl.stateAt(t as number)).toThrow(`stateAt(t): must be a number in [0, 20] (got ${got})`);
    expect(() => tl.stateAt(20.000001)).toThrow(RangeError);
    // Past the horizon, the message says how to get there (after an idle prolong it read like a dead end).
    expect(() => tl.stateAt(25)).toThrow(
      "stateAt(t): must be a number in [0, 20] (got 25): the history is computed up to 20, call prolongTo(25) first",
    );
    expect(() => tl.stateAt(-1)).toThrow(RangeError);
    expect(Object.is(tl.stateAt(-0).time, 0)).toBe(true);
    expect(tl.stateAt(-0)).toEqual(tl.stateAt(0));
  });

  it("setActions refuses a list that is not an array, naming actions (null threw a raw TypeError)", () => {
    const tl = wallAndHeavyDisc();
    const before = tl.getSnapshot();
    for (const [bad, got] of [
      [null, "null"],
      [undefined, "undefined"],
      [new Set(tl.actions), "an object"],
      [{ 0: tl.actions[0], length: 1 }, "an object"],
    ]) {
      const call = () => tl.setActions(bad as unknown as Action[]);
      expect(call).toThrow(SceneError);
      expect(call).toThrow(`actions: must be an array of actions (got ${got})`);
    }
    expect(tl.getSnapshot()).toBe(before);
  });

  it("prolongSlice refuses a budget that is not a whole number >= 1 by name (1.5 was named the World's maxEvents)", () => {
    const tl = wallAndHeavyDisc();
    for (const [budget, got] of [
      [1.5, "1.5"],
      [0, "0"],
      [-1, "-1"],
      [Number.NaN, "NaN"],
      ["5", 'the string "5"'],
    ]) {
      const call = () => tl.prolongSlice({ time: 1 }, budget as number);
      expect(call).toThrow(SceneError);
      expect(call).toThrow(`budget: must be a whole number >= 1, or Infinity (got ${got})`);
    }
    expect(tl.horizon).toBe(20);
    expect(tl.prolongSlice({ time: 1 }, Number.POSITIVE_INFINITY)).toMatchObject({ done: true, horizon: 21 });
  });

  it("prolongSlice after a prolongTo aims at a new target (it reported done at once, the old target passed)", () => {
    // a disc bouncing between two walls for ever: an event every 8 s
    const tl = new Timeline({ g: 0 });
    tl.apply({ time: 0, type: "addLine", id: "L", p1: [0, -10], p2: [0, 10], kind: "line" });
    tl.apply({ time: 0, type: "addLine", id: "R", p1: [10, -10], p2: [10, 10], kind: "line" });
    tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1, v: [1, 0] });
    const first = tl.prolongSlice({ time: 100 }, 1);
    expect(first.done).toBe(false);
    tl.prolongTo(500);
    const res = tl.prolongSlice({ time: 100 }, Number.POSITIVE_INFINITY);
    expect(res).toMatchObject({ done: true, horizon: 600, reason: "time" });
  });

  it("eventRange takes Infinity as the end, meaning to the end of the log (the end is clamped anyway)", () => {
    const tl = wallAndHeavyDisc();
    expect(tl.eventRange(30, Number.POSITIVE_INFINITY)).toEqual(tl.eventRange(30, tl.eventCount));
    expect(tl.eventRange(0, Number.POSITIVE_INFINITY)).toHaveLength(tl.eventCount);
    expect(() => tl.eventRange(Number.POSITIVE_INFINITY, 3)).toThrow(
      "eventRange(start): must be an integer >= 0 (got Infinity)",
    );
    expect(() => tl.eventRange(0, Number.NEGATIVE_INFINITY)).toThrow(
      "eventRange(end): must be an integer >= 0 or Infinity (got -Infinity)",
    );
  });

  it("eventAction(i) tells what a log entry of type 'action' did (the log gave only the id)", () => {
    const tl = wallAndHeavyDisc();
    tl.apply({ time: 4, type: "setGlobal", g: 2 });
    tl.apply({ time: 3, type: "giveVelocity", id: "a", v: [0, 1] }); // before it: the indices shift
    const found: Action[] = [];
    for (let i = 0; i < tl.eventCount; i++) {
      const action = tl.eventAction(i);
      expect(action !== null).toBe(tl.event(i).type === "action");
      if (action) {
        expect(action.time).toBe(tl.event(i).time);
        found.push(action);
      }
    }
    expect(found).toEqual(tl.actions);
    expect(found[3]).toBe(tl.actions[3]);
    expect(found.map((x) => x.type)).toEqual(["addLine", "addBody", "addBody", "giveVelocity", "setGlobal"]);
    tl.setActions(tl.actions.filter((x) => x.type !== "giveVelocity")); // undo, from a keyframe
    expect(tl.eventRange(0, Number.POSITIVE_INFINITY).flatMap((_e, i) => tl.eventAction(i) ?? [])).toEqual(
      tl.actions,
    );
    expect(Object.isFrozen(found[3])).toBe(true);
    expect(() => tl.eventAction(tl.eventCount)).toThrow(
      `eventAction(index): must be an integer in [0, ${tl.eventCount}) (got ${tl.eventCount})`,
    );
    expect(() => tl.eventAction(0.5)).toThrow(RangeError);
  });

  it("an action entry of the log carries the action's type; collisions and stops have no 'action' key", () => {
    const tl = wallAndHeavyDisc();
    tl.apply({ time: 4, type: "setGlobal", g: 2 });
    tl.apply({ time: 3, type: "giveVelocity", id: "a", v: [0, 1] });
    const log = tl.eventRange(0, Number.POSITIVE_INFINITY);
    log.forEach((e, i) => {
      if (e.type === "action") expect(e.action).toBe(tl.eventAction(i)?.type);
      else expect("action" in e).toBe(false);
    });
    expect(log.filter((e) => e.type === "action").map((e) => e.action)).toEqual([
      "addLine",
      "addBody",
      "addBody",
      "giveVelocity",
      "setGlobal",
    ]);
  });

  it("a prolong that ends in a Zeno state tells the listeners (the horizon moved, the revision did not)", () => {
    // a frictionless disc pushing a braking one: collisions and stops converge to t ≈ 52.249
    const zeno = (): Timeline => {
      const tl = new Timeline({ g: 0.5 });
      for (const a of CONVERGING_PAIR) tl.apply(a);
      return tl;
    };
    for (const run of [
      (tl: Timeline) => tl.prolong({ time: 60 }),
      (tl: Timeline) => tl.prolongTo(60),
      (tl: Timeline) => tl.prolongSlice({ time: 60 }, Number.POSITIVE_INFINITY),
    ]) {
      const tl = zeno();
      const seen: number[] = [];
      tl.subscribe(() => seen.push(tl.horizon));
      const revision = tl.getSnapshot();
      expect(() => run(tl)).toThrow(SimulationError);
      expect(tl.horizon).toBeGreaterThan(52);
      expect(tl.getSnapshot()).not.toBe(revision);
      expect(seen).toEqual([tl.horizon]);
    }
  });

  it("a listener that throws after a Zeno stop does not hide the SimulationError", () => {
    const tl = new Timeline({ g: 0.5 });
    for (const a of CONVERGING_PAIR) tl.apply(a);
    tl.subscribe(() => {
      throw new Error("listener");
    });
    expect(() => tl.prolong({ time: 60 })).toThrow(SimulationError);
  });
});
