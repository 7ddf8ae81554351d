/**
 * A Timeline without history applies an action at the horizon as one group with the actions applied
 * at that instant before it, also after the events they caused were computed: the result is the one
 * a Timeline with history and one built from scratch give (audit of session 20: without history the
 * action came after those events, and a push at once followed by a second push gave other physics).
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { disc, num, seedFor } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** Two touching discs at rest: a push of `a` towards `b` starts a collision at once. */
const TOUCHING: Action[] = [disc("a", 0, 0), disc("b", 2, 0)];

/** Bodies and counts at t, bit for bit (Object.is on every number through JSON of the bits). */
function outcome(tl: Timeline, t: number): string {
  const s = tl.stateAt(t);
  return JSON.stringify({ bodies: s.bodies, counts: tl.counts() });
}

/** The same timeline built from scratch from its own scene, computed to t. */
function fromScratch(tl: Timeline, t: number): string {
  const ref = Timeline.fromScene(tl.toScene());
  ref.prolongTo(t);
  return outcome(ref, t);
}

describe("Timeline without history: actions at the horizon's instant", () => {
  it("a second push at the instant of a first one that started a collision joins its group", () => {
    for (const history of [true, false]) {
      const tl = new Timeline({ g: 0, history });
      tl.setActions(TOUCHING);
      tl.apply({ time: 2, type: "giveVelocity", id: "a", v: [1, 0] });
      tl.prolongTo(2); // the collision at t = 2 is computed
      tl.apply({ time: 2, type: "giveVelocity", id: "b", v: [0, 1] });
      tl.apply({ time: 2, type: "giveVelocity", id: "a", v: [2, 0] });
      tl.prolongTo(10);
      // a's push and b's push are one group; then a gives b its velocity along x: b goes (2, 1)
      const b = tl.stateAt(10).bodies.find((x) => x.id === "b");
      expect(b).toMatchObject({ x: 18, y: 8, vx: 2, vy: 1 });
      expect(outcome(tl, 10)).toBe(fromScratch(tl, 10));
    }
  });

  it("a refused action at that instant changes nothing, and a valid one still joins the group", () => {
    const tl = new Timeline({ g: 0, history: false });
    tl.setActions(TOUCHING);
    tl.apply({ time: 2, type: "giveVelocity", id: "a", v: [1, 0] });
    const before = outcome(tl, 2);
    // c overlaps b where b stands at t = 2 (at x = 2): refused, the instant as computed
    expect(() => tl.apply({ time: 2, type: "addBody", id: "c", x: 3, y: 0, r: 1, m: 1 })).toThrow(/^action/);
    expect(outcome(tl, 2)).toBe(before);
    expect(tl.actions).toHaveLength(3);
    tl.apply({ time: 2, type: "giveVelocity", id: "b", v: [0, 1] });
    tl.prolongTo(10);
    expect(outcome(tl, 10)).toBe(fromScratch(tl, 10));
  });

  it("is refused, saying why, when the instant's actions came from setActions (no record of them)", () => {
    const tl = new Timeline({ g: 0, history: false });
    tl.setActions([...TOUCHING, { time: 2, type: "giveVelocity", id: "a", v: [1, 0] }]);
    tl.prolongTo(2);
    expect(() => tl.apply({ time: 2, type: "giveVelocity", id: "b", v: [0, 1] })).toThrow(
      /^action\.time: must be after 2: the events that instant's actions caused are computed, and without history/,
    );
    expect(tl.actions).toHaveLength(3);
  });

  it("an action at the horizon after events no action caused there is applied forward, as before", () => {
    // a reaches b at t = 1 (an event at the horizon, no action at t = 1): c added there
    const tl = new Timeline({ g: 0, history: false });
    tl.setActions([disc("a", 0, 0, [1, 0]), disc("b", 3, 0)]);
    tl.prolongTo(1);
    tl.apply({ time: 1, type: "addBody", id: "c", x: 10, y: 0, r: 1, m: 1 });
    tl.prolongTo(20);
    expect(outcome(tl, 20)).toBe(fromScratch(tl, 20));
  });

  /** A velocity component: 0 or 0.1…3 in size. */
  const component = fc.oneof(fc.constant(0), num(0.1, 3), num(-3, -0.1));

  it("random pushes of touching discs at a few instants, computed to each in between, give the history's result", () => {
    const push = fc.record({
      id: fc.constantFrom("a", "b", "c"),
      v: fc.tuple(component, component),
      prolong: fc.boolean(),
    });
    const instants = fc.array(fc.array(push, { minLength: 1, maxLength: 4 }), { minLength: 1, maxLength: 3 });
    fc.assert(
      fc.property(instants, (groups) => {
        const start: Action[] = [disc("a", 0, 0), disc("b", 2, 0), disc("c", 1, Math.sqrt(3))];
        const lines: Action[] = [
          { time: 0, type: "addLine", id: "L", p1: [-10, -10], p2: [-10, 10], kind: "line" },
          { time: 0, type: "addLine", id: "R", p1: [12, -10], p2: [12, 10], kind: "line" },
          { time: 0, type: "addLine", id: "B", p1: [-10, -10], p2: [12, -10], kind: "line" },
          { time: 0, type: "addLine", id: "T", p1: [-10, 12], p2: [12, 12], kind: "line" },
        ];
        const runs = [true, false].map((history) => {
          const tl = new Timeline({ g: 0, history });
          tl.setActions([...lines, ...start]);
          groups.forEach((group, k) => {
            const t = k + 1;
            for (const p of group) {
              tl.apply({ time: t, type: "giveVelocity", id: p.id, v: p.v });
              if (p.prolong) tl.prolongTo(t);
            }
          });
          tl.prolongTo(groups.length + 3);
          return tl;
        });
        const end = groups.length + 3;
        const [withHistory, headless] = runs as [Timeline, Timeline];
        expect(outcome(headless, end)).toBe(outcome(withHistory, end));
        expect(outcome(headless, end)).toBe(fromScratch(headless, end));
      }),
      { seed: seedFor("headless instant"), numRuns: 60, verbose: true },
    );
  });
});
