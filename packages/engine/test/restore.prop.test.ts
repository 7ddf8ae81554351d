// A World rebuilt from exact motions (World.addBodyMotion) continues exactly like the World the
// motions came from: the restart points of the Timeline rely on it. Each property prints its seed;
// set FC_SEED to explore other seeds.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { ChapgameError } from "../src/sim/errors.js";
import { World } from "../src/sim/world.js";
import { GRID_MIN_BODIES } from "../src/tolerances.js";
import { outcome } from "./outcome.js";
import { randomScene } from "./randomScene.js";
import { worldFromSpec } from "./worldFromSpec.js";

const SEED = Number(process.env.FC_SEED ?? 20261122);

function params<T extends unknown[]>(name: string, numRuns: number): fc.Parameters<T> {
  console.log(`[${name}] fast-check seed ${SEED} (set FC_SEED to change)`);
  return { seed: SEED, numRuns, verbose: true };
}

/** A new World at `w`'s time holding its globals, obstacles and every body's exact motion. */
function rebuilt(w: World): World {
  const out = new World({ g: w.g, gravity: w.gravity, time: w.time });
  for (const l of w.lines()) out.addLine(l.id, l.p1, l.p2, l.kind);
  for (const p of w.points()) out.addPoint(p.id, p.p);
  for (const b of w.bodies()) {
    const m = w.motion(b.id);
    out.addBodyMotion(b.id, { t0: m.t0, x0: m.x0, y0: m.y0, vx: m.vx, vy: m.vy, r: b.r, m: b.m, mu: b.mu });
  }
  out.setZenoWatch(w.zenoWatch());
  return out;
}

describe("World rebuilt from motions (addBodyMotion)", () => {
  it("continues bit for bit like the original, from any stopping point, on random scenes", () => {
    let gridRuns = 0;
    fc.assert(
      fc.property(
        fc.integer({ min: 0, max: 2 ** 31 - 1 }),
        fc.integer({ min: 0, max: 1500 }),
        fc.boolean(),
        (seed, before, big) => {
          const spec = randomScene(seed, {
            minBodies: big ? GRID_MIN_BODIES : 1,
            maxBodies: big ? 70 : 12,
            mode: "any",
            obstacles: true,
            infiniteMasses: true,
          });
          const original = worldFromSpec(spec);
          const first = outcome(original, before);
          fc.pre(first.error === null);
          if (spec.bodies.length >= GRID_MIN_BODIES) gridRuns++;
          const copy = rebuilt(original);
          expect(copy.bodies()).toStrictEqual(original.bodies());
          const a = outcome(original, 1500);
          const b = outcome(copy, 1500);
          expect(b).toStrictEqual(a);
          expect(copy.time).toBe(original.time);
          expect(copy.bodies()).toStrictEqual(original.bodies());
        },
      ),
      params("restore", 60),
    );
    // The broad-phase grid (and its cell crossings) must have been part of what was compared.
    expect(gridRuns).toBeGreaterThanOrEqual(10);
  });

  it("rebuilt in the middle of simultaneous events (Newton's cradle, stopped after each event)", () => {
    const make = (): World => {
      const w = new World({ g: 0 });
      for (let i = 0; i < 5; i++) w.addBody(`c${i}`, { x: 2 * i, y: 0, r: 1, m: 1 });
      w.addBody("striker", { x: -5, y: 0, r: 1, m: 1, vx: 3 });
      return w;
    };
    const whole = outcome(make(), 100).events;
    expect(whole.length).toBeGreaterThan(3);
    for (let k = 1; k < whole.length; k++) {
      const w = make();
      const head = outcome(w, k).events;
      const tail = outcome(rebuilt(w), 100).events;
      expect([...head, ...tail]).toStrictEqual(whole);
    }
  });

  it("round-trips motion(): a friction motion from the past evaluates to the same state now", () => {
    const w = new World({ g: 2 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, mu: 0.3, vx: 4, vy: -1 });
    w.advance({ untilTime: 0.75 });
    const m = w.motion("a");
    const v = new World({ g: 2, time: 0.75 });
    v.addBodyMotion("a", { t0: m.t0, x0: m.x0, y0: m.y0, vx: m.vx, vy: m.vy, r: 1, m: 1, mu: 0.3 });
    expect(v.motion("a")).toStrictEqual(m);
    expect(v.body("a")).toStrictEqual(w.body("a"));
  });

  it("refuses bad motions with an error naming the field, and changes nothing", () => {
    const w = new World({ g: 10, time: 5 });
    w.addBody("wall", { x: 0, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    const base = { t0: 4, x0: 10, y0: 0, vx: 0, vy: 0, r: 1, m: 1, mu: 0.5 };
    const field = (init: Partial<typeof base>, id = "b"): string => {
      try {
        w.addBodyMotion(id, { ...base, ...init });
      } catch (e) {
        expect(e).toBeInstanceOf(ChapgameError);
        return (e as ChapgameError).path;
      }
      return "accepted";
    };
    expect(field({ t0: 5.5 })).toBe("t0");
    expect(field({ t0: Number.NaN })).toBe("t0");
    // Speed 10 under mu g = 5 stops after 2 s, at t = 2 < 5: the body should be at rest by now.
    expect(field({ t0: 0, vx: 10 })).toBe("t0");
    expect(field({ x0: Number.POSITIVE_INFINITY })).toBe("x0");
    expect(field({ r: -1 })).toBe("r");
    expect(field({ m: 0 })).toBe("m");
    expect(field({ mu: -0.1 })).toBe("mu");
    expect(field({ x0: 1.5 })).toBe("x"); // overlaps "wall"
    expect(field({}, "wall")).toBe("id");
    expect(w.bodies().map((b) => b.id)).toEqual(["wall"]);
    // A round-off overlap (1e-12 of the contact distance) is accepted, as collisions leave them.
    expect(field({ x0: 2 - 2e-12 })).toBe("accepted");
  });
});
