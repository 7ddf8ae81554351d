// A read before the earliest readable time names the time asked, the earliest readable time, and
// how to keep more history: without history (history: false) the earliest is the last logged event
// or action; after forgetBefore, the start of the kept history.
import { describe, expect, it } from "vitest";
import { disc, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

function message(f: () => unknown): string {
  try {
    f();
  } catch (e) {
    expect(e).toBeInstanceOf(RangeError);
    return (e as Error).message;
  }
  return "no error";
}

describe("reads before the earliest readable time", () => {
  it("without history: the time asked, the last logged entry, and history: true", () => {
    const tl = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0), { history: false });
    tl.apply({ time: 2, type: "giveVelocity", id: "b", v: [0, 1] });
    tl.prolongTo(5);
    const why =
      "this timeline keeps no history (history: false), so the earliest readable time is 2, its last logged event or action: to read earlier times, create the Timeline with history: true (the default)";
    expect(message(() => tl.stateAt(1))).toBe(`stateAt(t): must be a number in [2, 5] (got 1): ${why}`);
    expect(message(() => tl.bodyArraysAt(0.5))).toBe(
      `bodyArraysAt(t): must be a number in [2, 5] (got 0.5): ${why}`,
    );
    expect(message(() => tl.path("b", 1.5))).toBe(`path(from): must be a number in [2, 5] (got 1.5): ${why}`);
    // from the earliest readable time on, reads answer
    expect(tl.stateAt(2).bodies[0]?.vy).toBe(1);
    expect(tl.bodyArraysAt(3).count).toBe(1);
  });

  it("after forgetBefore: the time asked, the start of the kept history, and how not to forget it", () => {
    const actions = [disc("a", 0, 0, [1, 0])];
    for (let k = 1; k <= 8; k++) actions.push({ time: k, type: "giveVelocity", id: "a", v: [1, k] });
    const tl = Timeline.fromScene(scene(actions, 0));
    tl.prolongTo(10);
    const start = tl.forgetBefore(5);
    expect(start).toBe(5);
    const log = `the log starts at entry ${tl.firstEvent} (t = 5)`;
    const why = `the history before 5 was forgotten (forgetBefore), so the earliest readable time is 5 (${log}): to keep it, call forgetBefore with an earlier time, or not at all`;
    expect(message(() => tl.stateAt(4))).toBe(`stateAt(t): must be a number in [5, 10] (got 4): ${why}`);
    expect(message(() => tl.eventIndexAt(4.5))).toBe(`eventIndexAt(t): must be >= 5 (got 4.5): ${why}`);
    expect(tl.stateAt(5).time).toBe(5);
  });

  it("a time before 0 or past the horizon keeps its own reason", () => {
    const tl = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0), { history: false });
    tl.prolongTo(5);
    expect(message(() => tl.stateAt(-1))).toBe("stateAt(t): must be a number in [0, 5] (got -1)");
    expect(message(() => tl.stateAt(6))).toBe(
      "stateAt(t): must be a number in [0, 5] (got 6): the history is computed up to 5, call prolongTo(6) first",
    );
  });
});
