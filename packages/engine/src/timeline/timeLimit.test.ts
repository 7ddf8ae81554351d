// The times a Timeline is asked to compute to are bounded by TIME_MAX, as the World's untilTime is
// (sim/timeLimit.ts): under gravity [0, -1e30], prolongTo(1e200) moved the horizon there and
// stateAt(1e200) gave y = -Infinity without a word. prolongTo's t, the horizon plus a prolong's
// until.time and an action's time plus its until.time past TIME_MAX are refused naming the field,
// the value and the time reached; nothing changes. A prolong by events, or with no bound, may still
// go past TIME_MAX.
import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import { parseScene } from "../scene/parse.js";
import type { Action } from "../scene/types.js";
import { TIME_MAX } from "../tolerances.js";
import { Timeline } from "./timeline.js";

function falling(): Timeline {
  const tl = new Timeline({ g: 0, gravity: [0, -1e30] });
  tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 });
  return tl;
}

function sceneError(run: () => unknown): SceneError {
  try {
    run();
  } catch (e) {
    expect(e).toBeInstanceOf(SceneError);
    return e as SceneError;
  }
  throw new Error("accepted");
}

describe("a Timeline computes to at most TIME_MAX", () => {
  it("refuses prolongTo(1e200) under gravity 1e30 (stateAt then gave y = -Infinity), naming t, the horizon unchanged", () => {
    const tl = falling();
    const e = sceneError(() => tl.prolongTo(1e200));
    expect(e.path).toBe("t");
    expect(e.reason).toMatch(/^must reach at most 1e\+30 \(TIME_MAX\) \(got 1e\+200\): past it/);
    expect(tl.horizon).toBe(0);
    tl.prolongTo(TIME_MAX);
    expect(tl.horizon).toBe(TIME_MAX);
    expect(tl.stateAt(TIME_MAX).bodies[0]?.y).toBe(-5.000000000000001e89);
  });
  it("refuses a prolong or prolongSlice whose until.time takes the horizon past TIME_MAX, naming until.time and the time reached", () => {
    const tl = falling();
    tl.prolongTo(1e29);
    for (const run of [() => tl.prolong({ time: 1e30 }), () => tl.prolongSlice({ time: 1e30 }, 10)]) {
      const e = sceneError(run);
      expect(e.path).toBe("until.time");
      expect(e.reason).toMatch(
        /^must reach at most 1e\+30 \(TIME_MAX\) \(got 1e\+30, reaching t = 1\.1e\+30 from the horizon 1e\+29\)/,
      );
    }
    expect(tl.horizon).toBe(1e29);
    expect(tl.prolong({ time: 9e29 }).reason).toBe("idle");
    expect(tl.horizon).toBe(TIME_MAX);
  });
  it("refuses an action whose until.time reaches past TIME_MAX, in apply and in a scene file, naming its until.time", () => {
    const tl = falling();
    const e = sceneError(() =>
      tl.apply({ time: 5, type: "giveVelocity", id: "a", v: [1, 0], until: { time: 1e200 } }),
    );
    expect(e.path).toBe("action.until.time");
    expect(e.reason).toMatch(/\(got 1e\+200, reaching t = 1e\+200 from the action's time 5\)/);
    expect(tl.actions.length).toBe(1);
    const file = {
      format: "chapgame",
      version: 1,
      actions: [{ time: 1e30, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, until: { time: 1e30 } }],
    };
    expect(sceneError(() => parseScene(JSON.stringify(file))).path).toBe("actions[0].until.time");
    // within the bound: 1e30 + 5e13 rounds to 1e30 (half an ulp is 7e13), the action's own time
    file.actions[0] = { ...file.actions[0], until: { time: 5e13 } } as (typeof file.actions)[0];
    expect(parseScene(JSON.stringify(file)).actions.length).toBe(1);
  });
  it("still prolongs past TIME_MAX by events", () => {
    const tl = new Timeline({ g: 0 });
    tl.apply({ time: 0, type: "addLine", id: "wall", p1: [1e30, 0], p2: [1e30, 1], kind: "line" });
    tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1e29, m: 1, v: [1e-30, 0] });
    expect(tl.prolong({ events: 1 }).events).toBe(1);
    expect(tl.horizon).toBeGreaterThan(TIME_MAX);
    expect(tl.stateAt(tl.horizon).bodies[0]?.vx).toBe(-1e-30);
    expect(tl.prolongTo(tl.horizon).events).toBe(0);
  });
  it("recomputes a history that events took past TIME_MAX after an edit in its past (apply, setActions), as a fresh timeline computes it", () => {
    // the recomputation asks the World for the old horizon, past TIME_MAX: it must not be refused
    const start: Action[] = [
      { time: 0, type: "addLine", id: "wall", p1: [1e30, 0], p2: [1e30, 1], kind: "line" },
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1e29, m: 1, v: [1e-30, 0] },
      { time: 0, type: "addBody", id: "b", x: 0, y: 5e29, r: 1e29, m: 1, v: [1e-30, 0] },
    ];
    const edit: Action = { time: 5, type: "giveVelocity", id: "b", v: [2e-30, 0] };
    const tl = new Timeline({ g: 0 });
    tl.setActions(start);
    tl.prolong({ events: 2 });
    const horizon = tl.horizon;
    expect(horizon).toBeGreaterThan(TIME_MAX);
    tl.apply(edit);
    expect(tl.horizon).toBe(horizon);
    const fresh = new Timeline({ g: 0 });
    fresh.setActions([...start, edit]);
    fresh.prolong({ events: 2 });
    expect(fresh.horizon).toBe(horizon);
    expect(tl.stateAt(horizon)).toEqual(fresh.stateAt(horizon));
    expect(tl.stateAt(horizon).bodies.map((b) => b.vx)).toEqual([-1e-30, -2e-30]);
    tl.setActions(start);
    expect(tl.horizon).toBe(horizon);
  });
  it("a read past TIME_MAX does not tell the user to call prolongTo there (which is refused), but how such a time is reached", () => {
    const tl = falling();
    const reads = [() => tl.stateAt(1e300), () => tl.bodyArraysAt(1e300), () => tl.path("a", 0, 1e300)];
    for (const read of reads) {
      let message = "";
      try {
        read();
      } catch (e) {
        expect(e).toBeInstanceOf(RangeError);
        message = (e as Error).message;
      }
      expect(message).toMatch(
        /must be a number in \[0, 0\] \(got 1e\+300\): the history is computed up to 0/,
      );
      expect(message).not.toMatch(/prolongTo\(1e\+300\)/);
      expect(message).toMatch(
        /past 1e\+30 \(TIME_MAX\) only events take a history \(prolong\(\{ events \}\)\)$/,
      );
    }
    expect(() => tl.stateAt(5)).toThrow(/call prolongTo\(5\) first$/);
  });
});
