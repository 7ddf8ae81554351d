// Adversarial scenes for the Zeno watch through the World: dense but legitimate runs of events
// that must pass, and states the exact model cannot pass that must be reported with a clear
// message (never looped over).
import { describe, expect, it } from "vitest";
import { SimulationError } from "./errors.js";
import { rackBreak, totals } from "./testSupport.js";
import { World } from "./world.js";

function thrown(f: () => unknown): unknown {
  try {
    f();
  } catch (e) {
    return e;
  }
  return null;
}

/**
 * A disc between a wall and an immovable disc moving at it (time of the crush: t0 + 7), all on one
 * line; and a second immovable disc moving away far from it, so that the trap watch's proof of a
 * crush in line (which needs the crusher to be the only immovable disc that moves: lineWatch.ts)
 * leaves it to the windows.
 */
function crush(t0: number): World {
  const w = new World({ g: 0, time: t0 });
  w.addLine("wall", [0, -10], [0, 10], "line");
  w.addBody("d", { x: 5, y: 0, r: 1, m: 1, vx: -10 });
  w.addBody("p", { x: 10, y: 0, r: 1, m: Number.POSITIVE_INFINITY, vx: -1 });
  w.addBody("far", { x: 100, y: 100, r: 1, m: Number.POSITIVE_INFINITY, vx: 1, vy: 1 });
  return w;
}

describe("Zeno watch: legitimate dense runs pass", () => {
  // Regression: the watch compared 200,000 events' progress with 1e-6 × |t|, so this steady rattle
  // (1e7 events per second) was refused as a Zeno state once t > 2e4.
  it("a disc rattling between walls 2.0001 r apart beside a moving immovable disc, at t = 1e5", () => {
    const w = new World({ g: 0, time: 1e5 });
    w.addLine("lo", [-10, 0], [10, 0], "line");
    w.addLine("hi", [-10, 2.0001], [10, 2.0001], "line");
    w.addBody("d", { x: 0, y: 1.00005, r: 1, m: 1, vy: 1e3 });
    w.addBody("pump", { x: 1000, y: 1000, r: 1, m: Number.POSITIVE_INFINITY, vx: 1 });
    expect(w.advance({ maxEvents: 1_000_000 })).toEqual({ events: 1_000_000, reason: "events" });
    const d = w.body("d");
    expect(Math.abs(d.vy)).toBe(1e3);
    // Times near 1e5 are rounded to 2^-36: positions at speed 1e3 are known to 1e3 × 2^-36.
    const slack = 1e3 * 2 ** -36;
    expect(d.y).toBeGreaterThanOrEqual(1 - slack);
    expect(d.y).toBeLessThanOrEqual(1.0001 + slack);
  });

  it("a Newton's cradle of 200 touching discs: 200 events at one instant, momentum passed on", () => {
    const w = new World({ g: 0 });
    for (let i = 0; i < 200; i++) w.addBody(`c${String(i).padStart(3, "0")}`, { x: 2 * i, y: 0, r: 1, m: 1 });
    w.addBody("cue", { x: -10, y: 0, r: 1, m: 1, vx: 5 });
    const times = new Set<number>();
    expect(w.advance({}, (e) => times.add(e.time))).toEqual({ events: 200, reason: "idle" });
    expect([...times]).toEqual([1.6]);
    expect(w.body("c199").vx).toBe(5);
    expect(
      w
        .bodies()
        .filter((b) => b.vx !== 0)
        .map((b) => b.id),
    ).toEqual(["c199"]);
  });
});

describe("Zeno watch: long finite bursts at one instant pass (bodies of very different masses)", () => {
  /** Galperin's billiard with the discs `gap` apart: the wall, a disc of mass 1 and one of mass M. */
  function galperinWorld(M: number, gap: number): World {
    const w = new World({ g: 0 });
    w.addLine("wall", [0, -10], [0, 10], "line");
    w.addBody("small", { x: 1 + gap, y: 0, r: 1, m: 1 });
    w.addBody("big", { x: 3 + 2 * gap, y: 0, r: 1, m: M, vx: -1 });
    return w;
  }

  // Regression (review, session 19): started touching, the README's billiard was refused as a Zeno
  // state from M = 1,700 on: its collisions all happen at t = 0, and the limit was 128 events.
  it("Galperin's billiard started touching: the digits of pi at one instant, as with a gap", () => {
    for (const [M, digits] of [
      [1e4, 314],
      [1e6, 3141],
      [1e10, 314159],
    ] as const) {
      const touching = galperinWorld(M, 0);
      const times = new Set<number>();
      expect(touching.advance({}, (e) => times.add(e.time))).toEqual({ events: digits, reason: "idle" });
      expect([...times]).toEqual([0]);
      expect(galperinWorld(M, 1e-3).advance({}).events).toBe(digits);
    }
  });

  it("a light disc between two heavy ones, all touching: a finite exchange at one instant", () => {
    const w = new World({ g: 0 });
    w.addBody("A", { x: 0, y: 0, r: 1, m: 1e6, vx: 1 });
    w.addBody("B", { x: 2, y: 0, r: 1, m: 1 });
    w.addBody("C", { x: 4, y: 0, r: 1, m: 1e6 });
    const r = w.advance({});
    expect(r.reason).toBe("idle");
    expect(r.events).toBeGreaterThan(2000);
    // momentum and energy kept through the burst
    const bodies = w.bodies();
    const p = bodies.reduce((s, b) => s + b.m * b.vx, 0);
    const e = bodies.reduce((s, b) => s + 0.5 * b.m * b.vx * b.vx, 0);
    expect(p).toBeCloseTo(1e6, 3);
    expect(e / 5e5).toBeCloseTo(1, 9);
  });

  it("a disc jammed between two immovable discs is still reported at once (infinite masses are no spread)", () => {
    const w = new World({ g: 0 });
    w.addBody("L", { x: 0, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("d", { x: 2, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody("R", { x: 4, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("far", { x: 100, y: 0, r: 1, m: 1e12 });
    const e = thrown(() => w.advance({}));
    expect(e).toBeInstanceOf(SimulationError);
    expect(String(e)).toMatch(/more than 257 events at the same instant t=0/);
  });

  // Regression (review, session 19): one collision of masses 1 and 1e20 elsewhere at the same
  // instant opened the mass-spread allowance to the jam: 67 million events (45 s) before the report.
  it("a jam is reported as soon when an unrelated pair of very different masses collides at that instant", () => {
    const w = new World({ g: 0 });
    w.addBody("zL", { x: 0, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("zd", { x: 2, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody("zR", { x: 4, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    w.addBody("a", { x: 100, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody("b", { x: 102, y: 0, r: 1, m: 1e20 });
    const e = thrown(() => w.advance({}));
    expect(e).toBeInstanceOf(SimulationError);
    expect(String(e)).toMatch(/more than \d+ events at the same instant t=0/);
    expect(Number(/more than (\d+) events/.exec(String(e))?.[1])).toBeLessThan(1000);
  });
});

describe("Zeno watch: states the model cannot pass are reported", () => {
  // Regression: the same crush converging on t = 0 instead of t = 7 ran 3e7 events and on (the
  // window was compared with 1e-6 × |t|, and |t| shrinks with the window).
  it("a disc crushed between a wall and a moving immovable disc, whatever the time origin", () => {
    for (const t0 of [0, -7, 1e6]) {
      const w = crush(t0);
      let events = 0;
      const e = thrown(() => w.advance({}, () => events++));
      expect(e).toBeInstanceOf(SimulationError);
      // Near t = 1e6 the intervals reach the rounding of t first: events at one instant.
      expect((e as Error).message).toMatch(
        t0 === 1e6 ? /at the same instant.*Zeno state/ : /events accumulate at a finite time/,
      );
      expect(events).toBeLessThan(4_000_000);
      expect(w.time).toBeLessThan(t0 + 7);
      expect(w.time).toBeGreaterThan(t0 + 6.999);
    }
  });

  it("a disc at rest in a V of two lines under gravity: resting contact, named", () => {
    // Slopes 3/4 so that the wedged position is exact: distance 4y/5 from both lines at y = 5/4.
    const w = new World({ g: 0, gravity: [0, -10] });
    w.addLine("left", [0, 0], [-8, 6], "segment");
    w.addLine("right", [0, 0], [8, 6], "segment");
    w.addBody("d", { x: 0, y: 1.25, r: 1, m: 1 });
    const e = thrown(() => w.advance({ untilTime: 10 }));
    expect(e).toBeInstanceOf(SimulationError);
    expect((e as Error).message).toMatch(/body "d" rests against "left" under an acceleration at t=0/);
  });

  // Regression: the Zeno watch counted the refused event before the response refused it, so from
  // the 64th retry on (64 events per body at one instant) the message turned into a Zeno state.
  it("retrying a resting contact gives the same message every time, and nextEventTime agrees", () => {
    const w = new World({ g: 0, gravity: [0, -10] });
    w.addLine("floor", [-10, 0], [10, 0], "segment");
    w.addBody("d", { x: 0, y: 1, r: 1, m: 1 });
    const expected = /^body "d" rests against "floor" under an acceleration at t=0/;
    for (let i = 0; i < 200; i++) {
      expect((thrown(() => w.nextEventTime()) as Error).message).toMatch(expected);
      expect((thrown(() => w.advance({ untilTime: 1 })) as Error).message).toMatch(expected);
    }
    expect(w.time).toBe(0);
    expect(w.body("d")).toMatchObject({ x: 0, y: 1, vx: 0, vy: 0 });
  });

  // Regression: with 64 events per body allowed at one instant, this rack was refused at the cue
  // ball's first contact ("more than 102465 events at the same instant"): the impulse passes
  // through 1,600 touching discs pair by pair, 140,613 events at t = 1.4964, and dies away.
  it("the break of a 40 x 40 rack of touching discs is no Zeno state (a long cascade at one instant)", () => {
    const w = new World({ g: 0 });
    for (const [id, b] of rackBreak(40, 0, 0.5, 50)) w.addBody(id, b);
    let atOnce = 0;
    let most = 0;
    let last = Number.NaN;
    const r = w.advance({ untilTime: 2 }, (e) => {
      atOnce = e.time === last ? atOnce + 1 : 1;
      last = e.time;
      most = Math.max(most, atOnce);
    });
    expect(r.reason).toBe("time");
    expect(most).toBeGreaterThan(64 * 1601);
    const { energy, px, py } = totals(w.bodies());
    expect(Math.abs(energy - 2500) / 2500).toBeLessThan(1e-12);
    expect(Math.abs(px - 100) / 100).toBeLessThan(1e-12);
    expect(Math.abs(py) / 100).toBeLessThan(1e-12);
  });

  // Regression: once the rounding loops of rack breaks were fixed (adversarialGraze.test), this
  // break ran on for ever: k10_07, pressed by k11_06, pushes the resting k09_08 against friction,
  // three events per 8e-14 s, each kick of k09_08 stopped by friction before it moves a bit.
  it("a disc pushed along against friction in a 30 x 30 rack break: a sustained push, named", () => {
    const w = new World({ g: 9.81 });
    for (const [id, b] of rackBreak(30, 0.1, 1.7, 40)) w.addBody(id, b);
    let events = 0;
    const e = thrown(() => w.advance({}, () => events++));
    expect(e).toBeInstanceOf(SimulationError);
    expect((e as Error).message).toMatch(/sustained push.*/);
    expect((e as Error).message).toMatch(/body "k09_08" stopped/);
    expect(events).toBeLessThan(1_000_000);
    expect(w.time).toBeGreaterThan(2.98);
    expect(w.time).toBeLessThan(2.99);
    // The throw counted nothing: advancing again stops at the same event with the same message.
    let again = 0;
    expect((thrown(() => w.advance({}, () => again++)) as Error).message).toBe((e as Error).message);
    expect(again).toBe(0);
  });
});
