// Bounds of the World's given times and masses (audit of session 19): a time beyond TIME_MAX (the
// World's `time` option) and a finite mass outside [MASS_MIN, MASS_MAX] are refused naming the
// field, the world unchanged; the bounds themselves are accepted; simulation itself may still run
// past TIME_MAX by events (only given times are bounded), and a Timeline restarts from such a time.
import { describe, expect, it } from "vitest";
import { type Keyframe, worldAt } from "../timeline/keyframe.js";
import { ChainCache } from "../timeline/keyframeChain.js";
import { MASS_MAX, MASS_MIN, TIME_MAX } from "../tolerances.js";
import { refusal } from "./testSupport.js";
import { World } from "./world.js";

describe("the World's time option is at most TIME_MAX in size", () => {
  it("refuses time 1e300 (bodies then sat at x = 1e300, beyond MAGNITUDE_MAX), naming time", () => {
    for (const time of [1e300, -1e300, 2 * TIME_MAX]) {
      const e = refusal(() => new World({ time }));
      expect(e.path).toBe("time");
      expect(e.reason).toMatch(/^must be at most 1e\+30 in size/);
    }
    expect(new World({ time: TIME_MAX }).time).toBe(TIME_MAX);
    expect(new World({ time: -TIME_MAX }).time).toBe(-TIME_MAX);
  });
  it("a world may still advance past TIME_MAX by events; its clone and a Timeline keyframe there keep that time", () => {
    // (an untilTime past TIME_MAX is refused: sim/timeLimit.test.ts)
    const w = new World({ g: 0, time: TIME_MAX });
    w.addBody("a", { x: 0, y: 0, r: 1e29, m: 1, vx: 1 });
    w.addLine("wall", [TIME_MAX, 0], [TIME_MAX, 1], "line");
    w.advance({ maxEvents: 1 });
    const past = w.time; // the contact, at TIME_MAX + 9e29
    expect(past / TIME_MAX).toBeCloseTo(1.9, 12);
    expect(w.clone().time).toBe(past);
    // A Timeline keyframe taken there (by simulation) is restored at its time.
    const kf = {
      time: past,
      g: 0,
      gravity: [0, 0],
      lines: [],
      points: [],
      full: { order: new Uint32Array(0), props: new Float64Array(0), motions: new Float64Array(0) },
      delta: null,
      zeno: w.zenoWatch(),
    } as unknown as Keyframe;
    expect(worldAt(kf, [], new ChainCache()).time).toBe(past);
  });
});

describe("masses are within [MASS_MIN, MASS_MAX], or Infinity", () => {
  it("refuses 5e-324 and 1e308 in addBody, updateBody and addBodyMotion, naming m, the world unchanged", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
    for (const m of [5e-324, MASS_MIN / 2, 1e308, MASS_MAX * 2]) {
      const edits: (() => unknown)[] = [
        () => w.addBody("b", { x: 5, y: 0, r: 1, m }),
        () => w.updateBody("a", { m }),
        () => w.addBodyMotion("b", { t0: 0, x0: 5, y0: 0, vx: 0, vy: 0, r: 1, m }),
      ];
      for (const edit of edits) {
        const e = refusal(edit);
        expect(e.path).toBe("m");
        expect(e.reason).toMatch(/^must be between 1e-40 and 1e\+40, or Infinity/);
      }
    }
    expect(w.bodies().map((b) => [b.id, b.m])).toEqual([["a", 1]]);
  });
  it("accepts the bounds, Infinity, a planet in kg and Galperin's 9-digit ratio 1e16", () => {
    const w = new World({ g: 0 });
    w.addBody("lo", { x: 0, y: 0, r: 1, m: MASS_MIN });
    w.addBody("hi", { x: 5, y: 0, r: 1, m: MASS_MAX });
    w.addBody("inf", { x: 10, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("earth", { x: 15, y: 0, r: 1, m: 5.97e24 });
    w.addBody("galperin", { x: 20, y: 0, r: 1, m: 1e16 });
    expect(w.bodyCount).toBe(5);
  });
  it("two discs of mass MASS_MAX collide head-on, swap velocities and report a finite impulse", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: MASS_MAX, vx: 1 });
    w.addBody("b", { x: 5, y: 0, r: 1, m: MASS_MAX, vx: -1 });
    const impulses: number[] = [];
    w.advance({ untilTime: 10 }, (e) => impulses.push(e.impulse));
    expect(impulses.length).toBe(1);
    expect((impulses[0] as number) / (2 * MASS_MAX)).toBeCloseTo(1, 14);
    expect([w.body("a").vx, w.body("b").vx]).toEqual([-1, 1]);
  });
});

// A World's clock is a coordinate: a negative start time is legitimate (the Zeno watch's verdicts
// are checked for scenes shifted in time, adversarialZeno.test.ts), unlike a Timeline's actions,
// whose clock starts at 0. The same scene started at -8 (an exact shift: every time is a multiple
// of 1/2 there) gives the same events, 8 earlier, and the same states.
describe("the World's time option may be negative", () => {
  function run(t0: number): { events: [string, number][]; x: number; vx: number } {
    const w = new World({ g: 0, time: t0 });
    w.addLine("wall", [0, -5], [0, 5], "line");
    w.addBody("a", { x: 5, y: 0, r: 1, m: 1, vx: -2 });
    w.addBody("b", { x: 9, y: 0, r: 1, m: 1, vx: -1 });
    const events: [string, number][] = [];
    w.advance({ untilTime: t0 + 10 }, (e) => events.push([e.kind, e.time - t0]));
    return { events, x: w.body("a").x, vx: w.body("a").vx };
  }
  it("runs a scene started at t = -8 as the one started at 0, shifted", () => {
    const shifted = run(-8);
    expect(shifted).toEqual(run(0));
    expect(shifted.events[0]).toEqual(["bodyLine", 2]);
    expect(shifted.events.length).toBeGreaterThan(2);
  });
  it("reads and edits at negative times, and advances across 0", () => {
    const w = new World({ g: 0, time: -3 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    expect(w.body("a", -1).x).toBe(2);
    w.advance({ untilTime: 2 });
    expect(w.time).toBe(2);
    expect(w.body("a").x).toBe(5);
  });
});
