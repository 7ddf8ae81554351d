// World.counts and World.opt are read-only for JavaScript callers too, not only in their types: a
// write throws (ES modules are strict) and changes nothing the World reports or does. Review of
// session 29: from plain JavaScript `world.counts.bodyBody = 5` was accepted and the World went on
// counting from 5, and `world.opt.broadPhase = false` switched the broad phase off mid-run.
import { inspect } from "node:util";
import { describe, expect, it } from "vitest";
import { World } from "./world.js";

function twoDiscs(): World {
  const w = new World({ g: 0 });
  w.addLine("wall", [0, -10], [0, 10], "line");
  w.addBody("small", { x: 5, y: 0, r: 1, m: 1 });
  w.addBody("big", { x: 10, y: 0, r: 1, m: 100, vx: -1 });
  return w;
}

describe("World.counts", () => {
  it("refuses a write (TypeError) and keeps counting what the World processed", () => {
    const w = twoDiscs();
    w.advance({ maxEvents: 3 });
    const counts = w.counts as { bodyBody: number };
    expect(() => {
      counts.bodyBody = 1000;
    }).toThrow(TypeError);
    expect(() => {
      (w.counts as unknown as Record<string, number>).extra = 1;
    }).toThrow(TypeError);
    w.advance({});
    expect({ ...w.counts }).toEqual(counted());
    expect(counted().bodyBody).toBe(16); // Galperin's billiard of mass ratio 100: 31 events
  });

  it("is one live object whose copies ({ ...counts }, JSON) are plain snapshots in the same key order", () => {
    const w = twoDiscs();
    const live = w.counts;
    const before = { ...w.counts };
    w.advance({});
    expect(w.counts).toBe(live);
    expect(before).toEqual({ bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0 });
    expect(JSON.stringify(live)).toBe(JSON.stringify(counted()));
    expect(Object.keys(live)).toEqual(["bodyBody", "bodyLine", "bodyPoint", "stop"]);
    // a World in a worker posts it (structured clone) as plain numbers; console.log shows them
    expect(structuredClone(live)).toEqual(counted());
    expect(inspect(live)).toBe(inspect(counted()));
    // a clone starts from a copy and counts on its own
    const c = w.clone();
    expect({ ...c.counts }).toEqual({ ...w.counts });
    expect(c.counts).not.toBe(w.counts);
  });
});

/** The counts of twoDiscs() run to the end, computed by a World nobody wrote into. */
function counted(): Record<string, number> {
  const w = twoDiscs();
  w.advance({});
  return { ...w.counts };
}

describe("World.opt", () => {
  it("refuses a write (TypeError): the switches stay those the World was made with", () => {
    const w = twoDiscs();
    const opt = w.opt as { broadPhase: boolean };
    expect(() => {
      opt.broadPhase = false;
    }).toThrow(TypeError);
    expect(w.opt.broadPhase).toBe(true);
    w.advance({});
    expect({ ...w.counts }).toEqual(counted());
    expect(new World({ optimizations: { broadPhase: false } }).opt.broadPhase).toBe(false);
  });
});
