import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import { galperin } from "../scene/presets.js";
import type { Action, SceneFile, Until } from "../scene/types.js";
import { Timeline } from "./timeline.js";
import type { TimelineOptions } from "./types.js";

describe("Timeline options", () => {
  it("refuses a misspelt or mistyped option instead of ignoring it (a history kept by a typo)", () => {
    const bad: [unknown, string][] = [
      // the internal `untils` (the CLI's) is not offered (audit of session 17: it was)
      [{ histroy: false }, "histroy: unknown field (known: g, gravity, history, compute)"],
      [{ history: "no" }, 'history: must be true or false (got the string "no")'],
      [{ compute: 0 }, "compute: must be true or false (got 0)"],
    ];
    for (const [options, message] of bad) {
      expect(() => new Timeline(options as TimelineOptions)).toThrow(message);
      expect(() => Timeline.fromScene(galperin(1), options as TimelineOptions)).toThrow(message);
    }
    expect(() => new Timeline({ g: -1 })).toThrow("g: must be a non-negative finite number");
    // fromScene takes g and gravity from the scene: given as options they were silently overridden
    expect(() => Timeline.fromScene(galperin(1), { g: 0 } as TimelineOptions)).toThrow(
      "g: unknown field (fromScene takes g and gravity from the scene)",
    );
  });

  it("refuses options that are not an object with the World's message, not a TypeError or a key named 0", () => {
    // Review of session 29: new Timeline(null) threw "Cannot destructure property 'untils' of 'o' as
    // it is null", new Timeline("x") "0: unknown field", new Timeline(5) and fromScene(scene, 5)
    // were accepted, fromScene(scene, null) threw "Cannot convert undefined or null to object".
    const known = "must be an object with fields g, gravity, history, compute";
    const notObjects: [unknown, string][] = [
      [null, "null"],
      ["x", 'the string "x"'],
      [5, "5"],
      [[], "an array of 0"],
      [false, "false"],
    ];
    for (const [options, got] of notObjects) {
      const message = `options: ${known} (got ${got})`;
      expect(() => new Timeline(options as TimelineOptions)).toThrow(message);
      expect(() => new Timeline(options as TimelineOptions)).toThrow(SceneError);
      expect(() => Timeline.fromScene(galperin(1), options as TimelineOptions)).toThrow(
        `options: must be an object with fields history, compute (got ${got})`,
      );
    }
    expect(new Timeline(undefined).history).toBe(true);
    expect(Timeline.fromScene(galperin(1), undefined).history).toBe(true);
  });

  it("accepts the documented ones", () => {
    expect(new Timeline({ g: 1, gravity: [0, -1], history: false, compute: true }).history).toBe(false);
    expect(Timeline.fromScene(galperin(1), { history: true, compute: false }).history).toBe(true);
    expect(new Timeline().history).toBe(true);
  });
});

describe("Timeline option untils (compute: false)", () => {
  /** A disc between two walls (it never rests), struck again at t = 2; `untils` are the addBody's
   *  and the strike's. */
  function bouncing(untils: [Until | undefined, Until | undefined]): SceneFile {
    const [add, strike] = untils;
    const actions: Action[] = [
      { time: 0, type: "addLine", id: "l", p1: [-10, -5], p2: [-10, 5], kind: "line" },
      { time: 0, type: "addLine", id: "r", p1: [10, -5], p2: [10, 5], kind: "line" },
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [3, 0], ...(add && { until: add }) },
      { time: 2, type: "giveVelocity", id: "a", v: [-5, 0], ...(strike && { until: strike }) },
    ];
    return { format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions };
  }

  it("computes, in slices, as far as the untils say: the history compute: true computes at once", () => {
    const cases: [Until | undefined, Until | undefined][] = [
      [{ time: 30 }, undefined],
      [{ time: 5 }, { events: 7 }],
      [{ events: 3 }, { time: 40, events: 100 }],
      [undefined, { time: 10 }],
    ];
    for (const untils of cases) {
      const scene = bouncing(untils);
      const eager = Timeline.fromScene(scene);
      const sliced = Timeline.fromScene(scene, { compute: false, untils: true });
      expect(sliced.horizon, "fromScene computes nothing").toBe(0);
      let calls = 0;
      while (!sliced.prolongSlice({ time: 2 }, 2).done) calls++;
      const what = JSON.stringify(untils);
      expect(calls, what).toBeGreaterThan(0);
      expect(sliced.horizon, what).toBe(eager.horizon);
      expect(sliced.counts(), what).toEqual(eager.counts());
      expect(sliced.stateAt(sliced.horizon), what).toEqual(eager.stateAt(eager.horizon));
      // without the option the untils are ignored: only up to the last action
      const plain = Timeline.fromScene(scene, { compute: false });
      plain.prolong({ time: 2 });
      expect(plain.horizon).toBe(2);
      expect(eager.horizon, what).toBeGreaterThan(2);
    }
  });

  it("refuses a value other than true or false", () => {
    expect(() => new Timeline({ untils: 1 } as unknown as TimelineOptions)).toThrow(
      "untils: must be true or false",
    );
  });
});

// The README said that with compute: false "nothing is computed until prolong", next to an apply
// of a future action; apply computes up to the action's time whatever the option (it checks the
// action there), and only setActions schedules (audit of session 22).
describe("a future action under compute: false", () => {
  const moving: Action = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] };
  const spawn: Action = { time: 10, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 };

  it("apply computes up to its time and refuses it there at once", () => {
    const tl = new Timeline({ g: 0, compute: false });
    tl.apply(moving);
    expect(tl.horizon).toBe(0);
    expect(() => tl.apply(spawn)).toThrow('action: body "b" would overlap body "a" at time 10');
    expect([tl.horizon, tl.actions.length]).toEqual([0, 1]);
    tl.apply({ ...spawn, x: 20 });
    expect(tl.horizon).toBe(10);
    expect(tl.stateAt(10).bodies.map((b) => [b.id, b.x])).toEqual([
      ["a", 10],
      ["b", 20],
    ]);
  });

  it("setActions only schedules it, keeping the history computed before it; the prolong checks it", () => {
    // Until session 22 the horizon went back to the keyframe setActions restarted from (0 here),
    // discarding the history computed up to 5 although nothing in it changed.
    const tl = new Timeline({ g: 0, compute: false });
    tl.setActions([moving]);
    tl.prolongTo(5);
    const before = tl.eventsBetween(0, 5);
    const at4 = tl.stateAt(4);
    tl.setActions([moving, spawn]);
    expect(tl.horizon).toBe(5);
    expect(tl.actions).toHaveLength(2);
    expect(tl.eventsBetween(0, 5)).toStrictEqual(before);
    expect(tl.stateAt(4)).toStrictEqual(at4);
    expect(() => tl.prolongTo(20)).toThrow('actions[1]: body "b" would overlap body "a" at time 10');
    expect(tl.horizon).toBe(10);
  });

  it("setActions with a change before the horizon still goes back to the keyframe before it", () => {
    const tl = new Timeline({ g: 0, compute: false });
    tl.setActions([moving]);
    tl.prolongTo(5);
    tl.setActions([moving, { ...spawn, time: 3, x: 20 }]);
    expect(tl.horizon).toBe(0); // the keyframe after the actions at 0
    tl.prolongTo(5);
    expect(tl.stateAt(5).bodies.map((b) => [b.id, b.x])).toEqual([
      ["a", 5],
      ["b", 20],
    ]);
  });
});
