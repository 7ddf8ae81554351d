// The range of times the World's queries answer, and advance's callback check (acceptance audit):
// a state after an event not yet processed was returned as if the discs passed through each other.
import { describe, expect, it } from "vitest";
import { ChapgameError } from "./errors.js";
import { World } from "./world.js";

/** a (r = 1) at x = 0 moving at 1 towards b (r = 2) at x = 10 moving at -1: contact at t = 3.5. */
function headOn(): World {
  const w = new World({ g: 0 });
  w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
  w.addBody("b", { x: 10, y: 0, r: 2, m: 1, vx: -1 });
  return w;
}

describe("World.body / bodies after the current time", () => {
  it("refuses a time after the next event, naming t and the event's time, before and after advancing", () => {
    const w = headOn();
    for (const query of [() => w.body("a", 10), () => w.bodies(10)]) {
      expect(query).toThrow(ChapgameError);
      expect(query).toThrow(/^t: must be at or before the next event at 3\.5 \(got 10\)/);
    }
    w.advance({ untilTime: 1 });
    expect(() => w.body("b", 3.6)).toThrow(/next event at 3\.5/);
  });

  it("refuses an infinite time even when nothing will ever happen (a disc gliding on was at NaN)", () => {
    const w = new World({ g: 0 });
    // an empty World too (review of session 26: bodies(NaN) gave [], bodyArrays(NaN) a time of NaN)
    for (const t of [Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => w.bodies(t)).toThrow(`t: must be a finite time (got ${t})`);
      expect(() => w.bodyArrays(t)).toThrow(`t: must be a finite time (got ${t})`);
    }
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    expect(w.nextEventTime()).toBe(Number.POSITIVE_INFINITY);
    // NaN is no time, not one before the body's motion (it was refused as that)
    for (const t of [Number.NaN, Number.POSITIVE_INFINITY, Number.NEGATIVE_INFINITY]) {
      expect(() => w.body("a", t)).toThrow(`t: must be a finite time (got ${t})`);
      expect(() => w.bodies(t)).toThrow(ChapgameError);
    }
    expect(w.body("a", 1e30).x).toBe(1e30);
    // past TIME_MAX a read is refused (sim/timeLimit.test.ts: under gravity it gave -Infinity)
    expect(() => w.body("a", 1e300)).toThrow(/^t: must reach at most 1e\+30 \(TIME_MAX\)/);
  });

  it("follows edits: the next event's time is found again after each change that can move it", () => {
    const w = headOn();
    expect(() => w.body("a", 5)).toThrow(/next event at 3\.5/);
    w.updateBody("a", { vx: 0 }); // b alone closes the gap of 7: contact at t = 7
    expect(w.body("a", 5)).toMatchObject({ x: 0 });
    expect(() => w.body("a", 8)).toThrow(/next event at 7 /);
    w.addLine("wall", [5, -10], [5, 10], "segment"); // b (r = 2) reaches it at t = 3
    expect(() => w.body("a", 5)).toThrow(/next event at 3 /);
    w.removeLine("wall");
    w.removeBody("b");
    expect(w.body("a", 1e9)).toMatchObject({ x: 0 });
  });

  it("answers up to the next event, that event's instant included, and changes nothing", () => {
    const w = headOn();
    expect(w.body("a", 3.5)).toMatchObject({ x: 3.5, vx: 1 });
    expect(w.bodies(2).map((b) => b.x)).toEqual([2, 8]);
    expect(w.time).toBe(0);
    const log: number[] = [];
    w.advance({}, (e) => log.push(e.time));
    expect(log).toEqual([3.5]);
    // Nothing is left: every later time is exact.
    expect(w.body("a", 100)).toMatchObject({ x: 3.5 - 96.5, vx: -1 });
    expect(w.body("b", 100)).toMatchObject({ x: 6.5 + 96.5, vx: 1 });
  });

  it("answers the same whether or not it was asked first (the check leaves the future as it was)", () => {
    const asked = headOn();
    asked.bodies(1);
    expect(() => asked.body("a", 5)).toThrow(ChapgameError);
    const plain = headOn();
    asked.advance({ untilTime: 50 });
    plain.advance({ untilTime: 50 });
    expect(asked.bodies()).toEqual(plain.bodies());
  });
});

describe("queries ahead change nothing an edit or an advance sees (review)", () => {
  /** 100 discs added one by one along a floor, each add followed (or not) by a query ahead. */
  function grow(ask: boolean): World {
    const w = new World({ g: 0.5 });
    w.addLine("floor", [-10, -2], [4000, -2], "segment");
    w.addPoint("pt", [50.5, 3]);
    for (let i = 0; i < 100; i++) {
      w.addBody(`b${String(i).padStart(4, "0")}`, {
        x: 3 * i,
        y: i % 3,
        r: 0.5,
        m: 1,
        vx: ((i * 7) % 5) - 2,
        vy: ((i * 3) % 5) - 2,
      });
      if (ask) expect(w.bodies(w.time + 0.01)).toHaveLength(i + 1);
    }
    return w;
  }

  it("the same events, end time and reason after them: a query rebuilt the grid tight, which moved the end of an idle advance", () => {
    const asked = grow(true);
    const plain = grow(false);
    const run = (w: World) => {
      const log: number[] = [];
      const r = w.advance({ maxEvents: 3000 }, (e) => log.push(e.time));
      return { log, r, time: w.time };
    };
    const a = run(asked);
    const b = run(plain);
    expect(a.log.length).toBeGreaterThan(50);
    expect(a.r.reason).toBe("idle"); // an idle advance ends at its last event (idleClock.test.ts)
    expect(a).toEqual(b);
  });
});

describe("World.advance's onEvent", () => {
  it("is checked before anything moves: a non-function is refused by name and the world stays as it was", () => {
    const w = headOn();
    const before = w.bodies();
    for (const bad of [5, "log", {}, null]) {
      expect(() => w.advance({}, bad as never)).toThrow(ChapgameError);
      expect(() => w.advance({}, bad as never)).toThrow(/^onEvent: must be a function/);
    }
    expect(w.time).toBe(0);
    expect(w.counts.bodyBody).toBe(0);
    expect(w.bodies()).toEqual(before);
  });
});
