// Contacts the doubles cannot place (audit of session 20): coordinates so large against the radii
// that the centres round onto each other (a NaN normal and an impulse of 0: the discs passed through
// each other) or onto a wall's line (taken for a Zeno state after 64 empty events). Each now throws
// a SimulationError that says so and names the participants, before anything changes; the same
// scene shifted near the origin collides normally.
import { describe, expect, it } from "vitest";
import { SimulationError } from "./errors.js";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

function caught(f: () => unknown): SimulationError {
  try {
    f();
  } catch (e) {
    if (e instanceof SimulationError) return e;
    throw e;
  }
  throw new Error("expected a SimulationError");
}

/** Two discs of radius 1 at x0 and x0 + 72 closing at 2: they touch at t = 35. */
function pair(x0: number): World {
  const w = new World({ g: 0 });
  w.addBody("a", { x: x0, y: 0, r: 1, m: 1, vx: 1 });
  w.addBody("b", { x: x0 + 72, y: 0, r: 1, m: 1, vx: -1 });
  return w;
}

describe("contacts beyond the resolution of doubles", () => {
  it("two discs whose centres round onto each other (x = 1e16, r = 1): an error naming both, nothing changed", () => {
    const w = pair(1e16);
    const before = JSON.stringify(w.bodies());
    expect(caught(() => w.nextEventTime()).message).toMatch(
      /^body "a" meets body "b" at t=35, where doubles/,
    );
    const e = caught(() => w.advance({ untilTime: 100 }));
    expect(e.ids).toEqual(["a", "b"]);
    expect(e.time).toBe(35);
    expect(e.message).toContain("the centres come out 0 apart for a contact distance of 2");
    expect(e.message).toContain("coordinates up to 1.00e+16");
    // the motions as before the event: b is still right of a when read at 35
    expect(w.body("b", 35).x).toBeGreaterThanOrEqual(w.body("a", 35).x);
    expect(JSON.stringify(w.bodies(0))).toBe(before);
    // trying again gives the same error, not a Zeno state: the refused event counts nothing (it
    // was counted before the check, and 128 retries made it a Zeno state of many events at one instant)
    for (let k = 0; k < 300; k++) expect(caught(() => w.advance({ untilTime: 100 })).message).toBe(e.message);
  });

  it("the same pair near the origin collides with a finite normal and exchanges velocities", () => {
    const w = pair(0);
    const seen: WorldEvent[] = [];
    w.advance({ untilTime: 100 }, (e) => seen.push({ ...e }));
    expect(seen).toHaveLength(1);
    expect(seen[0]).toMatchObject({ time: 35, kind: "bodyBody", nx: 1, ny: 0, px: 36, py: 0, impulse: 2 });
    expect(w.body("a").vx).toBe(-1);
  });

  it("a disc meeting a point where the doubles round its centre onto the point", () => {
    const w = new World({ g: 0 });
    w.addPoint("p", [1e16 + 40, 0]);
    w.addBody("a", { x: 1e16, y: 0, r: 1, m: 1, vx: 1 });
    const e = caught(() => w.advance({ untilTime: 100 }));
    expect(e.ids).toEqual(["a", "p"]);
    expect(e.message).toMatch(
      /^body "a" meets "p" at t=\d+, where doubles cannot place the contact \(the centre and the point come out 0 apart/,
    );
  });

  it("a disc whose centre the time's rounding puts on a wall's line: that error, not a Zeno state", () => {
    const w = new World({ g: 0 });
    w.addLine("wall", [0, -1], [0, 1], "line");
    w.addBody("a", { x: 1e17, y: 0, r: 1, m: 1, vx: -1 });
    const e = caught(() => w.advance({ untilTime: 2e17 }));
    expect(e.ids).toEqual(["a", "wall"]);
    expect(e.message).toContain("the centre and the line come out 0 apart for a contact distance of 1");
    expect(e.message).toContain("or of the time 100000000000000000 times a speed of 1.00");
    expect(w.counts.bodyLine).toBe(0);
  });

  it("a motion restored with t0 far in the past: the error names its start and its starting place", () => {
    // (session 30: t0 = x0 = -1e20 at speed 1 puts the body at x = 0, but its place moves in steps of
    // ulp(1e20) = 16384; the message blamed "the time 8" and "coordinates up to 10")
    const w = new World({ g: 0 });
    w.addBodyMotion("b", { t0: -1e20, x0: -1e20, y0: 0, vx: 1, vy: 0, r: 1, m: 1, mu: 0 });
    w.addBody("c", { x: 10, y: 0, r: 1, m: 1 });
    const e = caught(() => w.advance({ untilTime: 100 }));
    expect(e.ids).toEqual(["b", "c"]);
    expect(e.message).toContain(
      "one rounding of coordinates up to 1.00e+20, or of the time 8 (its motion started at t=-100000000000000000000: the time since then) times a speed of 1.00,",
    );
  });

  it("a rests-against error names the body and the obstacle too", () => {
    const w = new World({ g: 0, gravity: [0, -1] });
    w.addLine("floor", [-10, 0], [10, 0], "line");
    w.addBody("r", { x: 0, y: 1, r: 1, m: 1 });
    const e = caught(() => w.advance({ untilTime: 1 }));
    expect(e.ids).toEqual(["r", "floor"]);
    expect(Object.isFrozen(e.ids)).toBe(true);
  });
});
