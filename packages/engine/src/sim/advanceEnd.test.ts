// Where `advance` ends when nothing is left to happen, and what it says: the same with and without
// the grid, whose cell crossings are internal items that must not show. Regression (review): the
// grid World ended an open-ended advance at its last cell crossing (t = 213.4) where the World
// without the grid stayed at its last event (t = 0), so every later edit landed elsewhere; and it
// said "time" for an advance to a time while only crossings were left, where the other said "idle".
import { describe, expect, it, vi } from "vitest";
import type { Optimizations, WorldEvent } from "./types.js";
import { World } from "./world.js";

/** 40 discs in a lattice, the columns flying apart (never meeting), or towards each other. */
function spread(opt: Optimizations, meet = false): World {
  const w = new World({ optimizations: opt });
  for (let i = 0; i < 40; i++) {
    const col = i % 8;
    const vx = meet ? (col < 4 ? 1 : -1) : col - 3.5;
    w.addBody(`b${i}`, { x: col * 5, y: Math.floor(i / 8) * 5, r: 1, m: 1, vx, vy: 0.1 });
  }
  return w;
}

const tryAdd = (w: World): string => {
  try {
    w.addBody("late", { x: 0, y: 0, r: 1, m: 1 });
    return "ok";
  } catch (e) {
    return (e as Error).message;
  }
};

describe("the end of an advance", () => {
  it("an advance with no limit that runs out of events stays at the last event, with or without the grid", () => {
    for (const meet of [false, true]) {
      const grid = spread({}, meet);
      const flat = spread({ broadPhase: false }, meet);
      const log: WorldEvent[] = [];
      expect(grid.advance({}, (e) => log.push({ ...e }))).toEqual(flat.advance());
      expect(grid.time).toBe(meet ? (log.at(-1) as WorldEvent).time : 0);
      expect(grid.time).toBe(flat.time);
      expect(grid.bodies()).toEqual(flat.bodies());
      // Later edits land at the same time, in the same state.
      expect(tryAdd(grid)).toBe(tryAdd(flat));
      expect(grid.advance({ untilTime: grid.time + 50 })).toEqual(
        flat.advance({ untilTime: flat.time + 50 }),
      );
      expect(grid.bodies()).toEqual(flat.bodies());
    }
  });

  it('an advance to a time says "idle" when no collision or stop is left, crossings or not', () => {
    const grid = spread({});
    const flat = spread({ broadPhase: false });
    expect(grid.advance({ untilTime: 1 })).toEqual({ events: 0, reason: "idle" });
    expect(flat.advance({ untilTime: 1 })).toEqual({ events: 0, reason: "idle" });
    expect(grid.time).toBe(1);
    // With a collision ahead it says "time", and the look-ahead changed nothing.
    const a = spread({}, true);
    const b = spread({}, true);
    expect(a.advance({ untilTime: 0.1 })).toEqual({ events: 0, reason: "time" });
    b.advance({ untilTime: 0.1 });
    const ea: WorldEvent[] = [];
    const eb: WorldEvent[] = [];
    a.advance({ maxEvents: 20 }, (e) => ea.push({ ...e }));
    b.advance({ maxEvents: 20 }, (e) => eb.push({ ...e }));
    expect(ea).toEqual(eb);
    expect(ea.length).toBe(20);
  });

  it("an idle world's later advances skip the look-ahead until an edit", () => {
    const w = spread({});
    expect(w.advance({ untilTime: 1 }).reason).toBe("idle");
    const peek = vi.spyOn(w, "nextEventTime");
    for (let t = 2; t < 50; t++) expect(w.advance({ untilTime: t })).toEqual({ events: 0, reason: "idle" });
    expect(peek).not.toHaveBeenCalled();
    // An edit that sets up a collision: the next advance looks ahead again and says so.
    w.updateBody("b0", { vx: -10, vy: 0 });
    w.addBody("target", { x: w.body("b0").x - 10, y: w.body("b0").y, r: 1, m: 1 });
    expect(w.advance({ untilTime: 49.5 })).toEqual({ events: 0, reason: "time" });
    expect(peek).toHaveBeenCalledTimes(1);
    vi.restoreAllMocks();
  });
});
