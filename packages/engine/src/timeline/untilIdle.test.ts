/**
 * An action's `until` that nothing left to happen cut short (the World went idle before its events)
 * still counts once a later action sets the scene moving again, as it does when the timeline is built
 * from scratch with both actions (audit of session 21: applied one call at a time, the until was
 * dropped at the idle point, so the horizon fell short of fromScene's; and a timeline with history,
 * whose edit at an instant with events restarts from a keyframe and rebuilds its goals, went further
 * than one without history given the same calls).
 */
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { Timeline } from "./timeline.js";

/** A disc with friction stopping at t = 2 (one event), its until asking for three. */
const SLOWED: Action[] = [
  { time: 0, type: "addLine", id: "w", p1: [10, -5], p2: [10, 5], kind: "line" },
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 1, v: [2, 0], until: { events: 3 } },
];

function scratch(tl: Timeline): { horizon: number; counts: unknown } {
  const ref = Timeline.fromScene(tl.toScene());
  return { horizon: ref.horizon, counts: ref.counts() };
}

describe("an until met only by idleness", () => {
  for (const history of [true, false]) {
    it(`counts on after a later action, as from scratch (history: ${history})`, () => {
      const tl = new Timeline({ g: 1, history });
      for (const a of SLOWED) tl.apply(a);
      expect(tl.horizon).toBe(2); // the stop, then nothing is left
      tl.apply({ time: 10, type: "giveVelocity", id: "a", v: [1, 0] });
      // the until's two other events: the stop at 11 (1 s at mu g = 1), nothing after it
      expect({ horizon: tl.horizon, counts: tl.counts() }).toEqual(scratch(tl));
      expect(tl.horizon).toBe(11);
      expect(tl.counts().stop).toBe(2);
    });
  }

  it("with and without history, an action joining an idle instant's group revives its until alike", () => {
    const calls: Action[] = [
      { time: 0, type: "addLine", id: "L", p1: [-10, -5], p2: [-10, 5], kind: "line" },
      { time: 0, type: "addLine", id: "R", p1: [20, -5], p2: [20, 5], kind: "segment" },
      { time: 0, type: "addBody", id: "c", x: 2, y: 0, r: 1, m: 3 },
      { time: 4, type: "setGlobal", g: 2, until: { events: 2 } }, // idle: nothing moves
      { time: 4, type: "giveVelocity", id: "c", v: [4, 0], until: { events: 1 } }, // R at 8.25, L at 15.25
      // at the instant of an event: with history a restart from the keyframe at 4, without it forward
      { time: 15.25, type: "giveVelocity", id: "c", v: [4, 0] },
    ];
    for (const history of [true, false]) {
      const tl = new Timeline({ g: 0, history });
      const horizons = calls.map((a) => {
        tl.apply(a);
        return tl.horizon;
      });
      expect(horizons).toEqual([0, 0, 0, 4, 15.25, 15.25]);
      expect({ horizon: tl.horizon, counts: tl.counts() }).toEqual(scratch(tl));
    }
  });
});
