/**
 * Where an advance without a time limit ends when nothing is left to happen: at the last event (or
 * where it started), not at the last cell crossing or stale prediction the queue held after it.
 * Before this was fixed (session 21), `time` after such an advance depended on the grid, and a
 * headless Timeline (whose horizon is that time) refused actions between the last event and it,
 * which a Timeline built from scratch accepts.
 * - A World that ran idle and then goes on to a later time gives, bit for bit, what a twin that went
 *   straight to that time gives (the clock's return re-predicts from the last event).
 * - A headless Timeline's horizon after an unbounded prolong is its last event.
 * The property logs its seed (fixed by default); explore others with FC_SEED=<n>.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { Timeline } from "../timeline/timeline.js";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

/** A striker `a` that hits `b` at t = 8 (b then flies off through the grid for ever), and a block
 *  of 400 resting discs above, so that the grid is fine enough for b to cross many cells. */
function strikerWorld(): World {
  const w = new World({ g: 0 });
  w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
  w.addBody("b", { x: 10, y: 0, r: 1, m: 1 });
  for (let i = 0; i < 40; i++)
    for (let j = 0; j < 10; j++) w.addBody(`c${i}_${j}`, { x: -50 + 4 * i, y: 20 + 4 * j, r: 1, m: 1 });
  return w;
}

const bits = (x: unknown) =>
  JSON.stringify(x, (_k, v) => (typeof v === "number" ? (Object.is(v, -0) ? "-0" : String(v)) : v));

describe("World: the clock after an advance that runs idle", () => {
  it("stops at the last event, not at the last cell crossing after it", () => {
    const w = strikerWorld();
    const seen: number[] = [];
    expect(w.advance({}, (e) => seen.push(e.time))).toEqual({ events: 1, reason: "idle" });
    expect(seen).toEqual([8]);
    expect(w.time).toBe(8);
    expect(w.body("b")).toMatchObject({ x: 10, vx: 1 });
    expect(w.nextEventTime()).toBe(Number.POSITIVE_INFINITY);
    // an idle advance with an event limit it does not reach ends there too
    const v = strikerWorld();
    expect(v.advance({ maxEvents: 5 })).toEqual({ events: 1, reason: "idle" });
    expect(v.time).toBe(8);
    // and one that processes no event stays where it started
    expect(v.advance({})).toEqual({ events: 0, reason: "idle" });
    expect(v.time).toBe(8);
  });

  it("going on to a later time, and editing there, equals a twin that went straight there", () => {
    const seed = seedFor("idle clock twin", 20261124);
    const scene = fc.record({
      n: fc.integer({ min: 1, max: 90 }),
      speeds: fc.array(fc.tuple(fc.integer({ min: -3, max: 3 }), fc.integer({ min: -3, max: 3 })), {
        minLength: 90,
        maxLength: 90,
      }),
      later: fc.integer({ min: 0, max: 400 }).map((k) => k / 10),
      kick: fc.tuple(fc.integer({ min: -2, max: 2 }), fc.integer({ min: -2, max: 2 })),
    });
    // cases that ran idle and then went on past their last event (the ones the fix is about)
    let wentOn = 0;
    fc.assert(
      fc.property(scene, ({ n, speeds, later, kick }) => {
        const build = () => {
          const w = new World({ g: 0 });
          for (let i = 0; i < n; i++) {
            const [vx, vy] = speeds[i] as [number, number];
            w.addBody(`d${i}`, { x: 3 * (i % 10), y: 3 * Math.floor(i / 10), r: 1, m: 1 + (i % 3), vx, vy });
          }
          return w;
        };
        const idle = build();
        const twin = build();
        const logA: WorldEvent[] = [];
        const logB: WorldEvent[] = [];
        const first = idle.advance({ maxEvents: 2000 }, (e) => logA.push({ ...e }));
        if (first.reason !== "idle") return; // a scene that keeps colliding says nothing here
        const last = logA.length > 0 ? (logA[logA.length - 1] as WorldEvent).time : 0;
        expect(idle.time).toBe(last);
        const t = last + later;
        idle.advance({ untilTime: t }, (e) => logA.push({ ...e }));
        twin.advance({ untilTime: t }, (e) => logB.push({ ...e }));
        if (t > last) wentOn++;
        idle.updateBody("d0", { vx: kick[0], vy: kick[1] });
        twin.updateBody("d0", { vx: kick[0], vy: kick[1] });
        idle.advance({ maxEvents: 2000 }, (e) => logA.push({ ...e }));
        twin.advance({ maxEvents: 2000 }, (e) => logB.push({ ...e }));
        expect(bits(logA)).toBe(bits(logB));
        expect(bits(idle.bodies())).toBe(bits(twin.bodies()));
        expect(idle.time).toBe(twin.time);
      }),
      { seed, numRuns: 60 },
    );
    expect(wentOn).toBeGreaterThan(20);
  });
});

describe("Timeline: the horizon after an unbounded prolong", () => {
  it("is the last event, and an action after it applies as from scratch (with or without history)", () => {
    for (const history of [true, false]) {
      const tl = new Timeline({ g: 0, history });
      tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 });
      tl.apply({ time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 });
      for (let i = 0; i < 40; i++)
        for (let j = 0; j < 10; j++)
          tl.apply({ time: 0, type: "addBody", id: `c${i}_${j}`, x: -50 + 4 * i, y: 20 + 4 * j, r: 1, m: 1 });
      tl.apply({ time: 0, type: "giveVelocity", id: "a", v: [1, 0] });
      expect(tl.prolong({}).reason).toBe("idle");
      expect(tl.horizon).toBe(8);
      tl.apply({ time: 20, type: "giveVelocity", id: "b", v: [-1, 0] });
      tl.prolongTo(60);
      const ref = Timeline.fromScene(tl.toScene());
      ref.prolongTo(60);
      expect(bits(tl.stateAt(60))).toBe(bits(ref.stateAt(60)));
      expect(tl.counts()).toEqual(ref.counts());
    }
  });
});
