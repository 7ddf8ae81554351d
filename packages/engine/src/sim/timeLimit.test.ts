// Times a World is asked to reach are bounded by TIME_MAX (tolerances.ts): under gravity [0, -1e30],
// advance({ untilTime: 1e200 }) succeeded and body(id).y was then -Infinity without a word, and the
// World went on accepting edits there (an updateBody gave a motion from y = -Infinity). Within
// |t| <= TIME_MAX the largest allowed motion stays finite; a limit past it is refused, naming the
// field and the value; Infinity (the default: no limit) and runs past TIME_MAX by events stay.
import { describe, expect, it } from "vitest";
import { TIME_MAX } from "../tolerances.js";
import { refusal } from "./testSupport.js";
import { World } from "./world.js";

function falling(time = 0): World {
  const w = new World({ g: 0, gravity: [0, -1e30], time });
  w.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
  return w;
}

describe("a World's time limits and read times are at most TIME_MAX", () => {
  it("refuses advance({ untilTime: 1e200 }) under gravity 1e30 (y came out -Infinity), naming untilTime, the world unchanged", () => {
    const w = falling();
    const e = refusal(() => w.advance({ untilTime: 1e200 }));
    expect(e.path).toBe("untilTime");
    expect(e.reason).toMatch(/^must reach at most 1e\+30 \(TIME_MAX\) \(got 1e\+200\): past it/);
    expect(e.reason).toMatch(/maxEvents/);
    expect(w.time).toBe(0);
    expect(w.body("a").y).toBe(0);
  });
  it("refuses every finite untilTime just past TIME_MAX, and accepts TIME_MAX itself and Infinity (the documented default)", () => {
    for (const t of [2 * TIME_MAX, 1e31, Number.MAX_VALUE])
      expect(refusal(() => falling().advance({ untilTime: t })).path).toBe("untilTime");
    const w = falling();
    expect(w.advance({ untilTime: Number.POSITIVE_INFINITY }).reason).toBe("idle");
    expect(w.time).toBe(0);
    w.advance({ untilTime: TIME_MAX });
    expect(w.time).toBe(TIME_MAX);
    expect(Number.isFinite(w.body("a").y)).toBe(true);
  });
  it("the largest allowed motions stay finite over the whole allowed span of time, -TIME_MAX to TIME_MAX", () => {
    const w = new World({ g: 1e30, gravity: [1e30, -1e30], time: -TIME_MAX });
    w.addBody("a", { x: -1e30, y: 1e30, r: 1e30, m: 1, vx: -1e30, vy: 1e30 });
    w.advance({ untilTime: TIME_MAX });
    const s = w.body("a");
    for (const v of [s.x, s.y, s.vx, s.vy]) expect(Number.isFinite(v)).toBe(true);
    expect(Math.abs(s.y)).toBeLessThan(1e91); // 2e90: (2e30)^2 × 1e30 / 2
  });
  it("refuses a read at a time past TIME_MAX (body, bodies, bodyArrays gave y = -Infinity), naming t", () => {
    const w = falling();
    for (const read of [() => w.body("a", 1e200), () => w.bodies(1e200), () => w.bodyArrays(1e200)]) {
      const e = refusal(read);
      expect(e.path).toBe("t");
      expect(e.reason).toMatch(/^must reach at most 1e\+30 \(TIME_MAX\) \(got 1e\+200\)/);
    }
    expect(w.body("a", TIME_MAX).y).toBe(-5.000000000000001e89);
  });
  it("still runs past TIME_MAX by events, and reads and advances to the clock's own time there", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1e29, m: 1, vx: 1e-30 });
    w.addLine("wall", [1e30, 0], [1e30, 1], "line");
    expect(w.advance({ maxEvents: 1 }).events).toBe(1);
    expect(w.time).toBeGreaterThan(TIME_MAX);
    expect(w.body("a", w.time).vx).toBe(-1e-30);
    expect(w.advance({ untilTime: w.time }).events).toBe(0);
    expect(refusal(() => w.advance({ untilTime: w.time * 2 })).path).toBe("untilTime");
  });
});
