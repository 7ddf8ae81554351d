/**
 * Edits that give nothing new (audit, session 18):
 * - updateBody with an empty patch, or with the body's own state passed back, keeps the motion, so
 *   the future is unchanged bit for bit (it restarted the motion, which changed the last bits of
 *   every later event: a replay recording only real inputs drifted from the live game);
 * - addBodyMotion refuses derived fields (ax, ay, tStop) that differ from what the World derives
 *   (they were silently ignored).
 */
import { describe, expect, it } from "vitest";
import { ChapgameError } from "./errors.js";
import { World } from "./world.js";

/** A small box with moving discs, friction on: events for a few seconds. */
function table(): World {
  const w = new World({ g: 9.81 });
  w.addLine("s", [0, 0], [20, 0], "segment");
  w.addLine("n", [0, 10], [20, 10], "segment");
  w.addLine("w", [0, 0], [0, 10], "segment");
  w.addLine("e", [20, 0], [20, 10], "segment");
  w.addBody("a", { x: 3, y: 3, r: 1, m: 1, mu: 0.05, vx: 7.3, vy: 2.1 });
  w.addBody("b", { x: 12, y: 6, r: 1, m: 2, mu: 0.05, vx: -3.7, vy: 1.3 });
  w.addBody("c", { x: 16, y: 2, r: 0.5, m: 1, mu: 0.05, vx: 0.9, vy: 5.5 });
  return w;
}

function finalState(edit: (w: World) => void): string {
  const w = table();
  w.advance({ untilTime: 1.2345 });
  edit(w);
  const times: number[] = [];
  w.advance({ untilTime: 8 }, (e) => times.push(e.time));
  return JSON.stringify({ times, bodies: w.bodies() });
}

describe("updateBody that changes nothing", () => {
  const untouched = finalState(() => {});

  it("an empty patch keeps the future bit for bit", () => {
    expect(finalState((w) => w.updateBody("a", {}))).toBe(untouched);
  });

  it("the body's own state passed back keeps the future bit for bit", () => {
    expect(finalState((w) => w.updateBody("a", w.body("a")))).toBe(untouched);
    expect(finalState((w) => w.updateBody("b", { vx: w.body("b").vx, m: 2 }))).toBe(untouched);
  });

  it("a real change still restarts the motion", () => {
    expect(finalState((w) => w.updateBody("a", { vx: w.body("a").vx * 0.5 }))).not.toBe(untouched);
  });

  it("a patch that changes nothing is still checked", () => {
    const w = table();
    expect(() => w.updateBody("a", { r: -1 })).toThrow(ChapgameError);
    expect(() => w.updateBody("nobody", {})).toThrow(ChapgameError);
  });
});

describe("addBodyMotion's checks", () => {
  it("refuses derived fields that differ from the World's, and takes its own motion back", () => {
    const w = table();
    w.advance({ untilTime: 0.5 });
    const m = w.motion("a");
    const rebuilt = new World({ g: 9.81, time: w.time });
    for (const [field, bad] of [
      ["ax", Number.NaN],
      ["ay", "x"],
      ["tStop", -3],
    ] as const) {
      let err: unknown = null;
      try {
        rebuilt.addBodyMotion("a", { ...m, r: 1, m: 1, mu: 0.05, [field]: bad });
      } catch (e) {
        err = e;
      }
      expect((err as ChapgameError).path).toBe(field);
    }
    expect(rebuilt.bodyCount).toBe(0);
    rebuilt.addBodyMotion("a", { ...m, r: 1, m: 1, mu: 0.05 });
    expect(rebuilt.motion("a")).toEqual(m);
  });
});

describe("a state the World reports beyond the edit bounds goes back in", () => {
  it("updateBody(id, body(id)) after gravity took the body past 1e30 keeps the motion (it was refused: y: must be at most 1e+30)", () => {
    const w = new World({ g: 0, gravity: [0, -10] });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    w.advance({ untilTime: 1e15 });
    const s = w.body("a");
    expect(s.y).toBe(-5e30);
    const motion = w.motion("a");
    w.updateBody("a", s);
    expect(w.motion("a")).toEqual(motion);
    // a strike keeps the own position, and a new value is still held to the bounds
    w.updateBody("a", { ...s, vx: 2 });
    expect(w.body("a")).toMatchObject({ x: s.x, y: s.y, vx: 2 });
    expect(() => w.updateBody("a", { y: s.y * 2 })).toThrow("y: must be at most 1e+30 in size (got -1e+31)");
  });
});
