/**
 * What happens at one instant (the order the README states): the events at time t come first, then
 * the actions at t, then the events those actions cause at t; stateAt(t) shows all of it. Edits at
 * exactly an event's time (next to a keyframe, too) equal building the edited scene from scratch.
 * A prolong stopped by an event limit may leave the horizon's instant partly computed.
 */
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { wallAndHeavyDisc } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** The same actions computed from nothing up to `horizon`. */
function fromScratch(actions: readonly Action[], horizon: number, g = 0): Timeline {
  const tl = new Timeline({ g });
  tl.setActions(actions);
  tl.prolongTo(horizon);
  return tl;
}

const log = (tl: Timeline) => tl.eventRange(0, tl.eventCount);
const kinds = (tl: Timeline, t: number) => tl.eventsBetween(t, t).map((e) => `${e.type} ${e.ids.join(",")}`);

describe("Timeline: one instant", () => {
  it("removing a body at the moment it collides: the collision happens first (b keeps its impulse)", () => {
    const tl = wallAndHeavyDisc();
    const hit = tl.event(3);
    expect(hit).toMatchObject({ time: 3, type: "bodyBody", ids: ["a", "b"] });
    tl.apply({ time: 3, type: "removeBody", id: "a" });
    expect(kinds(tl, 3)).toEqual(["bodyBody a,b", "action a"]);
    const b = tl.stateAt(3).bodies;
    expect(b.map((s) => s.id)).toEqual(["b"]);
    expect(b[0]?.vx).toBe(-0.9801980198019802); // (100 - 1) / 101: the collision's outcome
    const ref = fromScratch(tl.actions, tl.horizon);
    expect(log(tl)).toEqual(log(ref));
    expect(tl.stateAt(20)).toEqual(ref.stateAt(20));
  });

  it("a velocity given at a collision's time can cause a second collision at the same instant", () => {
    const tl = wallAndHeavyDisc();
    tl.apply({ time: 3, type: "giveVelocity", id: "a", v: [0, 1] });
    expect(kinds(tl, 3)).toEqual(["bodyBody a,b", "action a", "bodyBody a,b"]);
    const a = tl.stateAt(3).bodies[0];
    expect(a?.vy).toBe(1);
    expect(a?.vx).toBeLessThan(0); // b, still pushing, hit it again
    expect(log(tl)).toEqual(log(fromScratch(tl.actions, tl.horizon)));
  });

  it("edits at exactly a logged event's time around keyframe boundaries equal building from scratch", () => {
    // two discs bouncing between walls: a keyframe every 1024 records
    const make = (): Timeline => {
      const tl = new Timeline({ g: 0 });
      tl.apply({ time: 0, type: "addLine", id: "L", p1: [0, -10], p2: [0, 10], kind: "line" });
      tl.apply({ time: 0, type: "addLine", id: "R", p1: [10, -10], p2: [10, 10], kind: "line" });
      tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1, v: [1, 0] });
      tl.apply({ time: 0, type: "addBody", id: "c", x: 5, y: 5, r: 1, m: 1, v: [3, 0] });
      tl.prolong({ events: 1100 });
      return tl;
    };
    const base = make();
    for (const i of [1022, 1023, 1024, 1025, 1026]) {
      const e = base.event(i);
      const id = e.ids[0] as string;
      for (const edit of [
        { time: e.time, type: "giveVelocity", id, v: [0.5, 0.25] },
        { time: e.time, type: "removeBody", id },
      ] as Action[]) {
        const tl = make();
        tl.apply(edit);
        const ref = fromScratch(tl.actions, tl.horizon);
        expect({ log: log(tl), end: tl.stateAt(tl.horizon) }).toEqual({
          log: log(ref),
          end: ref.stateAt(ref.horizon),
        });
      }
    }
  });

  it("after a prolong stopped by an event limit, the horizon's instant may be partly computed", () => {
    // a and b reach the wall at t = 4 together; one event per prolong
    const tl = new Timeline({ g: 0 });
    tl.apply({ time: 0, type: "addLine", id: "L", p1: [0, -10], p2: [0, 10], kind: "line" });
    tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1, v: [-1, 0] });
    tl.apply({ time: 0, type: "addBody", id: "b", x: 5, y: 5, r: 1, m: 1, v: [-1, 0] });
    expect(tl.prolong({ events: 1 })).toEqual({ events: 1, reason: "events" });
    expect(tl.horizon).toBe(4);
    expect(tl.stateAt(4).bodies.map((s) => s.vx)).toEqual([1, -1]);
    tl.apply({ time: 4, type: "giveVelocity", id: "b", v: [0, 1] }); // after b's bounce, as from scratch
    expect(kinds(tl, 4)).toEqual(["bodyLine a,L", "bodyLine b,L", "action b"]);
    expect(log(tl)).toEqual(log(fromScratch(tl.actions, 4)));
    expect(tl.stateAt(4).bodies.map((s) => [s.vx, s.vy])).toEqual([
      [1, 0],
      [0, 1],
    ]);
  });
});
