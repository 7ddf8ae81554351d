// The README's "What it cannot do" gives recipes for what the engine lacks (review of session 25,
// from a pool break and a pinball scene written against the docs): a pocket is an obstacle whose
// event removes the disc (in a World's callback, or as a Timeline action at the entry's time, to be
// found again after an edit in the past), and obstacles never move (updateLine teleports, refused
// onto a disc, pushing nothing). These tests hold the README to them.
import { type Action, ChapgameError, Timeline, World } from "@chapgame/engine";
import { describe, expect, it } from "vitest";

/** A ball rolling (no friction) towards a pocket's mouth: a segment across x = 10. */
const table: Action[] = [
  { time: 0, type: "addLine", id: "mouth", p1: [10, -2], p2: [10, 2], kind: "segment" },
  { time: 0, type: "addLine", id: "back", p1: [-10, -20], p2: [-10, 20], kind: "segment" },
  { time: 0, type: "addBody", id: "ball", x: 0, y: 0, r: 1, m: 1, v: [3, 0] },
];

/** Computes 20 s and removes the ball at the first entry where it touches the mouth. */
function pot(tl: Timeline): number | null {
  tl.prolongTo(20);
  for (let i = 0; i < tl.eventCount; i++) {
    const e = tl.event(i);
    if (e.type === "bodyLine" && e.ids[1] === "mouth") {
      tl.apply({ time: e.time, type: "removeBody", id: e.ids[0] });
      return e.time;
    }
  }
  return null;
}

describe("README recipes: pockets and obstacles that do not move", () => {
  it("a World removes the ball from inside the callback of its event at the mouth", () => {
    const w = new World({ g: 0 });
    w.addLine("mouth", [10, -2], [10, 2], "segment");
    w.addBody("ball", { x: 0, y: 0, r: 1, m: 1, vx: 3 });
    const kinds: string[] = [];
    w.advance({ untilTime: 20 }, (e) => {
      kinds.push(`${e.kind} ${e.b}`);
      if (e.kind === "bodyLine" && e.b === "mouth") w.removeBody(e.a);
    });
    expect(kinds).toEqual(["bodyLine mouth"]);
    expect(w.hasBody("ball")).toBe(false);
  });

  it("a Timeline logs the touch, then the removeBody action at the same time; the ball is gone", () => {
    const tl = new Timeline({ g: 0 });
    tl.setActions(table);
    const t = pot(tl);
    expect(t).toBe(3); // from x = 0 at speed 3 to touching x = 10 with r = 1
    const at = tl.eventsBetween(3, 3).map((e) => `${e.type} ${e.ids.join(",")}`);
    expect(at).toEqual(["bodyLine ball,mouth", "action ball"]);
    expect(tl.stateAt(3).bodies).toEqual([]);
  });

  it("after an edit in the past, the removals after it are dropped and found again (as built from scratch)", () => {
    const tl = new Timeline({ g: 0 });
    tl.setActions(table);
    expect(pot(tl)).toBe(3);
    // at t = 1 the ball is sent back: the old removal at t = 3 names a ball that no longer gets there
    const edit: Action = { time: 1, type: "giveVelocity", id: "ball", v: [-3, 0] };
    tl.setActions([...tl.actions.filter((a) => !(a.type === "removeBody" && a.time > edit.time)), edit]);
    const again = pot(tl);
    // back from x = 3 at t = 1 to the back wall (touching at x = -9), then out to the mouth
    expect(again).toBe(1 + 12 / 3 + 18 / 3);
    const fresh = new Timeline({ g: 0 });
    fresh.setActions([...table, edit]);
    expect(pot(fresh)).toBe(again);
    expect(fresh.eventRange(0, Infinity)).toEqual(tl.eventRange(0, Infinity));
  });

  it("an obstacle moved onto a disc is refused; moved next to a resting disc, it pushes nothing", () => {
    const w = new World({ g: 0 });
    w.addLine("flipper", [0, 0], [4, 0], "segment");
    w.addBody("ball", { x: 2, y: 1.5, r: 1, m: 1 });
    let refusal: unknown;
    try {
      w.updateLine("flipper", { p1: [0, 1], p2: [4, 1] });
    } catch (e) {
      refusal = e;
    }
    expect(refusal).toBeInstanceOf(ChapgameError);
    expect((refusal as Error).message).toBe('p1: the line would overlap body "ball"');
    w.updateLine("flipper", { p1: [0, 0.4], p2: [4, 0.4] });
    w.advance({ untilTime: 5 });
    expect(w.body("ball")).toMatchObject({ x: 2, y: 1.5, vx: 0, vy: 0 });
  });
});
