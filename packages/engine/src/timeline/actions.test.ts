/** Actions on a Timeline, validated against the simulated state at their time. */
import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import { parseScene } from "../scene/parse.js";
import { dilutedGas, newtonsCradle } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { disc, fingerprint, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

describe("actions and their validation against the simulated state", () => {
  const moving = () => Timeline.fromScene(scene([disc("a", 0, 0, [1, 0]), disc("far", 100, 100)]));

  it("refuses a body added where another has moved to (overlap at t > 0), and changes nothing", () => {
    const tl = moving();
    tl.prolongTo(10);
    const before = fingerprint(tl);
    const rev = tl.getSnapshot();
    // at t = 5 body a is at (5, 0)
    expect(() => tl.apply(disc("b", 5.5, 0, [0, 0], 5))).toThrow(
      'action: body "b" would overlap body "a" at time 5',
    );
    expect(() => tl.apply(disc("b", 15.5, 0, [0, 0], 15))).toThrow(
      'action: body "b" would overlap body "a" at time 15',
    );
    expect(fingerprint(tl)).toEqual(before);
    expect(tl.getSnapshot()).toBe(rev);
    tl.apply(disc("b", 5.5, 0, [0, 0], 1)); // at t = 1, a is at (1, 0): fine
    expect(tl.getSnapshot()).not.toBe(rev);
  });

  it("refuses growing into an overlap, a line across a moving body, actions on ids gone at that time", () => {
    const tl = moving();
    tl.prolongTo(10);
    tl.apply({ time: 6, type: "removeBody", id: "far" });
    const before = fingerprint(tl);
    const refusals: [Action, string][] = [
      [
        { time: 4, type: "updateBody", id: "far", r: 200 },
        'action: body "far" would overlap body "a" at time 4',
      ],
      [
        { time: 3, type: "addLine", id: "w", p1: [3, -5], p2: [3, 5], kind: "segment" },
        'action: line "w" would overlap body "a" at time 3',
      ],
      [
        { time: 3, type: "addPoint", id: "p", p: [3.5, 0] },
        'action: point "p" would overlap body "a" at time 3',
      ],
      [{ time: 7, type: "giveVelocity", id: "far", v: [1, 1] }, 'action.id: no body "far" at time 7'],
      [
        { time: 5, type: "addBody", id: "a", x: 50, y: 50, r: 1, m: 1 },
        'action.id: body "a" already exists at time 5',
      ],
      [{ time: -1, type: "removeBody", id: "a" }, "action.time: must be a non-negative finite number"],
    ];
    for (const [a, msg] of refusals) {
      expect(() => tl.apply(a)).toThrow(SceneError);
      expect(() => tl.apply(a)).toThrow(msg);
      expect(fingerprint(tl)).toEqual(before);
    }
  });

  it("refuses an action in the past that makes a later action invalid, and changes nothing", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0), disc("b", 10, 0, [0, 0], 5)]));
    tl.prolongTo(8);
    const before = fingerprint(tl);
    // sending a towards x = 10 puts it where b is added at t = 5; the later action is named by its
    // index in tl.actions (it was its index in the list with the refused action inserted: actions[2])
    expect(() => tl.apply({ time: 1, type: "giveVelocity", id: "a", v: [2.5, 0] })).toThrow(
      'actions[1]: body "b" would overlap body "a" at time 5 (once this action is in place)',
    );
    expect(tl.actions[1]).toMatchObject({ type: "addBody", id: "b" });
    expect(() => tl.apply({ time: 0.5, type: "removeBody", id: "b" })).toThrow('action.id: no body "b"');
    expect(fingerprint(tl)).toEqual(before);
    tl.apply({ time: 6, type: "giveVelocity", id: "b", v: [1, 0] });
    expect(() => tl.apply({ time: 5.5, type: "removeBody", id: "b" })).toThrow(
      'actions[2].id: no body "b" at time 6 (once this action is in place)',
    );
    expect(tl.actions[2]).toMatchObject({ type: "giveVelocity", id: "b" });
  });

  it("fromScene refuses what parseScene cannot see: an overlap with a body that moved", () => {
    const s = scene([disc("a", 0, 0, [1, 0]), disc("b", 4.5, 0, [0, 0], 3)]);
    expect(() => parseScene(s)).not.toThrow();
    expect(() => Timeline.fromScene(s)).toThrow('actions[1]: body "b" would overlap body "a" at time 3');
  });

  it("a file's actions are named by their place in the file, also when a later prolong applies them (compute: false)", () => {
    // Audit of session 15: the CLI (compute: false) named actions[2] for the file's actions[0].
    const s = scene([disc("b", 10, 0, [0, 0], 1), disc("a", 0, 0, [10, 0])]);
    expect(() => Timeline.fromScene(s)).toThrow('actions[0]: body "b" would overlap body "a" at time 1');
    const lazy = Timeline.fromScene(s, { compute: false });
    expect(() => lazy.prolongTo(2)).toThrow('actions[0]: body "b" would overlap body "a" at time 1');
    // after an apply, indices are those of tl.actions (time order) again
    const applied = Timeline.fromScene(s, { compute: false });
    applied.apply({ time: 0, type: "addPoint", id: "p", p: [0, 50] });
    expect(applied.actions[2]).toMatchObject({ type: "addBody", id: "b" });
    expect(() => applied.prolongTo(2)).toThrow('actions[2]: body "b" would overlap body "a" at time 1');
  });

  it("setActions is atomic: an invalid list leaves the timeline as it was", () => {
    const tl = moving();
    tl.prolongTo(5);
    const before = fingerprint(tl);
    expect(() => tl.setActions([disc("a", 0, 0), disc("b", 1, 0)])).toThrow(
      'actions[1]: body "b" would overlap body "a" at time 0',
    );
    expect(() => tl.setActions([disc("a", 0, 0), { time: 1, type: "removeBody", id: "x" }])).toThrow(
      'actions[1].id: no body "x" at time 1',
    );
    expect(fingerprint(tl)).toEqual(before);
  });

  it("undo/redo by setActions in a long history restarts from a World keyframe and equals from scratch", () => {
    const s = dilutedGas({ n: 100, packing: 0.2, seed: 4 });
    const tl = Timeline.fromScene(s);
    tl.prolong({ events: 40_000 });
    const H = tl.horizon;
    const late: Action = { time: 0.9 * H, type: "giveVelocity", id: "d7", v: [0.5, 0.5] };
    tl.apply(late);
    const withLate = Timeline.fromScene({ ...s, actions: [...s.actions, late] });
    withLate.prolongTo(H);
    expect(tl.eventsBetween(0.85 * H, H)).toEqual(withLate.eventsBetween(0.85 * H, H));
    tl.setActions(s.actions);
    const original = Timeline.fromScene(s);
    original.prolongTo(H);
    expect(tl.eventsBetween(0.85 * H, H)).toEqual(original.eventsBetween(0.85 * H, H));
    expect(tl.stateAt(H)).toEqual(original.stateAt(H));
    expect(tl.counts()).toEqual(original.counts());
  });

  it("a take-back by setActions on a compute: false timeline restarts from the keyframe, not from 0", () => {
    // Session 16: the editor's host (compute: false) took a refused edit back with setActions,
    // which recomputed the whole history from t = 0.
    const s = dilutedGas({ n: 100, packing: 0.2, seed: 4 });
    const tl = Timeline.fromScene(s, { compute: false });
    tl.prolong({ events: 40_000 });
    const H = tl.horizon;
    const late: Action = { time: 0.9 * H, type: "giveVelocity", id: "d7", v: [0.5, 0.5] };
    tl.apply(late);
    tl.setActions(s.actions);
    // back at the last keyframe before the changed action, far past 0
    expect(tl.horizon).toBeGreaterThan(0.8 * H);
    expect(tl.horizon).toBeLessThan(0.9 * H);
    tl.prolongTo(H);
    const original = Timeline.fromScene(s, { compute: false });
    original.prolongTo(H);
    expect(tl.eventsBetween(0.85 * H, H)).toEqual(original.eventsBetween(0.85 * H, H));
    expect(tl.stateAt(H)).toEqual(original.stateAt(H));
    expect(tl.counts()).toEqual(original.counts());
  });

  it("events an action causes at its own time are part of the state at that time (touching cradle at t = 0)", () => {
    const s = newtonsCradle();
    const striker = s.actions.find((a) => a.type === "addBody" && a.id === "striker");
    if (striker?.type === "addBody") striker.x = -2; // touching c1, moving towards it
    const tl = Timeline.fromScene(s);
    tl.prolongTo(0);
    expect(tl.stateAt(0).bodies.map((b) => b.vx)).toEqual([0, 0, 0, 0, 4, 0]);
    expect(tl.counts().bodyBody).toBe(5);
    // the same actions one apply() at a time, and one more at t = 0 afterwards (recomputed)
    const one = new Timeline({ g: s.g });
    for (const a of s.actions) one.apply(a);
    expect(one.eventsBetween(0, 0)).toEqual(tl.eventsBetween(0, 0));
    const extra: Action = { time: 0, type: "addPoint", id: "p", p: [50, 50] };
    one.apply(extra);
    const scratch = Timeline.fromScene({ ...s, actions: [...s.actions, extra] });
    scratch.prolongTo(0);
    expect(one.eventsBetween(0, 0)).toEqual(scratch.eventsBetween(0, 0));
    expect(one.stateAt(0)).toEqual(scratch.stateAt(0));
  });

  it("an action's until computes that far ahead: seconds, events, or until idle", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0), disc("b", 10, 0)]));
    expect(tl.horizon).toBe(0);
    tl.apply({ time: 1, type: "giveVelocity", id: "a", v: [1, 0], until: { time: 2.5 } });
    expect(tl.horizon).toBe(3.5);
    tl.apply({ time: 4, type: "giveVelocity", id: "b", v: [-1, 0], until: { events: 1 } });
    expect(tl.counts().bodyBody).toBe(1);
    expect(tl.horizon).toBeCloseTo(4 + (10 - 3 - 2) / 2, 12); // at t = 4: a at 3, b at 10, closing at 2
    tl.apply({ time: tl.horizon, type: "setGlobal", g: 1, until: {} });
    expect(tl.counts().bodyBody).toBe(1);
  });

  it("subscribe is called after every change, getSnapshot changes with it, unsubscribe stops it", () => {
    const tl = moving();
    let calls = 0;
    const off = tl.subscribe(() => calls++);
    const r0 = tl.getSnapshot();
    tl.prolong({ time: 1 });
    tl.apply(disc("c", 50, 0, [0, 0], 0.5));
    tl.setActions(tl.actions);
    expect(calls).toBe(3);
    expect(tl.getSnapshot()).toBe(r0 + 3);
    off();
    tl.prolong({ time: 1 });
    expect(calls).toBe(3);
  });

  it("toScene round-trips: the same actions and the same history", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.2, seed: 9 }));
    tl.apply({ time: 2, type: "giveVelocity", id: "d3", v: [3, -1] });
    tl.apply({ time: 1, type: "setGlobal", g: 2 });
    tl.prolongTo(6);
    const back = Timeline.fromScene(tl.toScene());
    back.prolongTo(6);
    expect(back.toScene()).toEqual(tl.toScene());
    expect(back.eventsBetween(0, 6)).toEqual(tl.eventsBetween(0, 6));
    expect(back.stateAt(6)).toEqual(tl.stateAt(6));
  });
});
