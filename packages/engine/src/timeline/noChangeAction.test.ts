/**
 * An action that changes nothing (updateBody with the body's own mass, giveVelocity with its own
 * velocity): the World keeps the body's motion (sim/edits.ts), and the Timeline's motion table and
 * keyframes must hold that same motion. When the table restarted the body at the action's time, a
 * rebuild from the keyframe after it (an edit later in the past, an undo) gave other event times
 * than the live computation in their last bits, and stateAt differed from the World (review,
 * session 18).
 */
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { World } from "../sim/world.js";
import { scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const BOX: Action[] = [
  { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
  { time: 0, type: "addLine", id: "n", p1: [0, 10], p2: [20, 10], kind: "segment" },
  { time: 0, type: "addLine", id: "w", p1: [0, 0], p2: [0, 10], kind: "segment" },
  { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 10], kind: "segment" },
  { time: 0, type: "addBody", id: "a", x: 3, y: 3, r: 1, m: 1, mu: 0.05, v: [7.3, 2.1] },
  { time: 0, type: "addBody", id: "b", x: 12, y: 6, r: 1, m: 2, mu: 0.05, v: [-3.7, 1.3] },
  { time: 0, type: "addBody", id: "c", x: 16, y: 2, r: 0.5, m: 1, mu: 0.05, v: [0.9, 5.5] },
];
const TE = 1.2345;
const SAME_MASS: Action = { time: TE, type: "updateBody", id: "a", m: 1 };
const LATER: Action = { time: 6, type: "addPoint", id: "far", p: [500, 500] };
const TIMES = [1.3, 2, 3.3, 5.9, 7.9];

const computed = (actions: Action[]) => {
  const tl = Timeline.fromScene(scene(actions));
  tl.prolongTo(8);
  return tl;
};
const shown = (tl: Timeline) =>
  JSON.stringify({ log: tl.eventsBetween(0, 5.999), states: TIMES.map((t) => tl.stateAt(t).bodies) });

describe("an action that changes nothing", () => {
  it("a rebuild from the keyframe after it equals the computation from scratch, bit for bit", () => {
    const rebuilt = computed([...BOX, SAME_MASS]);
    rebuilt.apply(LATER); // restores the keyframe after the action and recomputes
    expect(shown(rebuilt)).toBe(shown(computed([...BOX, SAME_MASS, LATER])));
    // undo: the same action list as a timeline that never had the later edit
    rebuilt.setActions([...BOX, SAME_MASS]);
    rebuilt.prolongTo(8);
    const live = computed([...BOX, SAME_MASS]);
    expect(JSON.stringify(rebuilt.eventsBetween(0, 8))).toBe(JSON.stringify(live.eventsBetween(0, 8)));
  });

  it("stateAt after it equals the World that made the history", () => {
    const tl = computed([...BOX, SAME_MASS]);
    const w = new World({ g: 9.81 });
    for (const a of BOX)
      if (a.type === "addLine") w.addLine(a.id, a.p1, a.p2, a.kind);
      else if (a.type === "addBody")
        w.addBody(a.id, { x: a.x, y: a.y, r: a.r, m: a.m, mu: a.mu, vx: a.v?.[0], vy: a.v?.[1] });
    w.advance({ untilTime: TE });
    w.updateBody("a", { m: 1 });
    const next = tl.nextEventTime(TE) as number;
    const t = (TE + next) / 2;
    w.advance({ untilTime: t });
    expect(tl.stateAt(t).bodies.find((b) => b.id === "a")).toEqual(w.body("a"));
  });
});
