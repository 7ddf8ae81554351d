// A line's two points must be at least RADIUS_MIN apart in x or y: closer, the direction's square
// underflowed and discs passed through the line or gained energy at it (review, session 19: p2 =
// p1 + 1e-170 gave no collision, 1e-160 a wrong time and 2e-5 more speed). At the bound itself
// a disc bounces exactly.
import { describe, expect, it } from "vitest";
import { parseScene } from "../scene/parse.js";
import { Timeline } from "../timeline/timeline.js";
import { RADIUS_MIN } from "../tolerances.js";
import { ChapgameError } from "./errors.js";
import { World } from "./world.js";

function refusal(f: () => unknown): { path: string; reason: string } | null {
  try {
    f();
  } catch (e) {
    if (e instanceof ChapgameError) return { path: e.path, reason: e.reason };
    throw e;
  }
  return null;
}

const sceneWithLine = (p2: [number, number]) =>
  JSON.stringify({
    format: "chapgame",
    version: 1,
    g: 0,
    gravity: [0, 0],
    actions: [{ time: 0, type: "addLine", id: "l", p1: [0, 0], p2, kind: "line" }],
  });

describe("a line's direction", () => {
  it("World.addLine and updateLine refuse points closer than RADIUS_MIN, naming the point", () => {
    const w = new World({ g: 0 });
    expect(refusal(() => w.addLine("l", [0, 0], [1e-170, 0], "line"))).toEqual({
      path: "p2",
      reason: `must be at least ${RADIUS_MIN} from p1 in x or y (got 1e-170): a shorter direction underflows the contact tests`,
    });
    expect(refusal(() => w.addLine("l", [3, 4], [3, 4], "ray"))?.reason).toBe(
      "must differ from p1 (got [3, 4])",
    );
    w.addLine("l", [0, 0], [1, 0], "line");
    expect(refusal(() => w.updateLine("l", { p2: [5e-31, 5e-31] }))?.path).toBe("p2");
    expect(w.lines()[0]?.p2).toEqual([1, 0]); // nothing changed
  });

  it("an end moved onto the other is refused naming the end that moved and the one it met", () => {
    // (review of session 25: updateLine's p1 moved onto p2 was refused as "p2: must differ from
    // p1" by the World, "p1: must differ from p1 and p2 of the line" by a Timeline)
    const w = new World({ g: 0 });
    w.addLine("l", [0, 0], [1, 0], "segment");
    expect(refusal(() => w.updateLine("l", { p1: [1, 0] }))).toEqual({
      path: "p1",
      reason: "must differ from p2 (got [1, 0])",
    });
    expect(refusal(() => w.updateLine("l", { p2: [0, 0] }))).toEqual({
      path: "p2",
      reason: "must differ from p1 (got [0, 0])",
    });
    expect(refusal(() => w.updateLine("l", { p1: [2, -0.5], p2: [2, -0.5] }))).toEqual({
      path: "p2",
      reason: "must differ from p1 (got [2, -0.5])",
    });
    const tl = Timeline.fromScene(parseScene(sceneWithLine([1, 0])));
    expect(refusal(() => tl.apply({ time: 1, type: "updateLine", id: "l", p1: [1, 0] }))).toEqual({
      path: "action.p1",
      reason: "must differ from p2 (got [1, 0])",
    });
    expect(refusal(() => tl.apply({ time: 1, type: "updateLine", id: "l", p2: [0, 0] }))).toEqual({
      path: "action.p2",
      reason: "must differ from p1 (got [0, 0])",
    });
  });

  it("a scene file's addLine and a Timeline's updateLine are refused the same way, naming the field", () => {
    expect(refusal(() => parseScene(sceneWithLine([1e-200, 0])))).toEqual({
      path: "actions[0].p2",
      reason: `must be at least ${RADIUS_MIN} from p1 in x or y (got 1e-200): a shorter direction underflows the contact tests`,
    });
    const tl = Timeline.fromScene(parseScene(sceneWithLine([1, 0])));
    expect(refusal(() => tl.apply({ time: 1, type: "updateLine", id: "l", p1: [1, 1e-31] }))).toEqual({
      path: "action.p1",
      reason: `must be at least ${RADIUS_MIN} from p2 in x or y (got 1e-31): a shorter direction underflows the contact tests`,
    });
  });

  it("at the bound a disc bounces off the line exactly: the time and the velocity of a long line", () => {
    for (const d of [RADIUS_MIN, 1]) {
      const w = new World({ g: 0 });
      w.addLine("l", [0, 0], [d, 0], "line");
      w.addBody("b", { x: 0, y: 5, r: 1, m: 1, vx: 0.3, vy: -1 });
      const hits: number[] = [];
      w.advance({ untilTime: 10 }, (e) => hits.push(e.time));
      expect(hits).toEqual([4]);
      expect(w.body("b")).toMatchObject({ vx: 0.3, vy: 1 });
    }
  });
});
