/**
 * World.bodyArrays: the reuse of `into` (the same object, arrays kept while the count is the same,
 * `ids` kept while the ids are), the cache of the bodies in id order following every edit, the
 * refusals (the same as bodies(t) for a bad t; `into` not a previous result), and (property, seed
 * printed) the same numbers as bodies(t) bit for bit on random scenes while they run.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { expectSameBodies, num, seedFor, speed } from "../timeline/testSupport.js";
import { ARRAY_FIELDS, type BodyArrays } from "./bodyArrays.js";
import { ChapgameError, SimulationError } from "./errors.js";
import { World } from "./world.js";

const RUNS = Number(process.env.RUNS ?? 40);

/** Three discs in a row, c moving towards b: contact at t = 2. */
function row(): World {
  const w = new World({ g: 0 });
  w.addBody("c", { x: 10, y: 0, r: 1, m: 1, vx: -2 });
  w.addBody("a", { x: -10, y: 0, r: 1, m: 1 });
  w.addBody("b", { x: 4, y: 0, r: 1, m: 1 });
  return w;
}

describe("World.bodyArrays reuses `into`", () => {
  it("returns into itself, with the same arrays and ids while the bodies are the same", () => {
    const w = row();
    const first = w.bodyArrays();
    expectSameBodies(first, 0, w.bodies());
    const arrays = ARRAY_FIELDS.map((f) => first[f]);
    const ids = first.ids;
    w.advance({ untilTime: 1.5 });
    const second = w.bodyArrays(1.5, first);
    expect(second).toBe(first);
    expect(second.ids).toBe(ids);
    expect(ARRAY_FIELDS.map((f) => second[f])).toStrictEqual(arrays);
    ARRAY_FIELDS.forEach((f, i) => {
      expect(second[f]).toBe(arrays[i]);
    });
    expectSameBodies(second, 1.5, w.bodies(1.5));
  });

  it("keeps into's ids when they hold the same ids, even as another array object", () => {
    const w = row();
    const into = w.bodyArrays();
    const copy = [...into.ids];
    into.ids = copy;
    expect(w.bodyArrays(0, into).ids).toBe(copy);
  });

  it("gives new ids, and the same arrays, when a body is replaced by another (same count)", () => {
    const w = row();
    const into = w.bodyArrays();
    const before = into.ids;
    const x = into.x;
    w.removeBody("b");
    w.addBody("d", { x: 4, y: 5, r: 1, m: 2 });
    w.bodyArrays(0, into);
    expect(into.ids).not.toBe(before);
    expect(before).toStrictEqual(["a", "b", "c"]); // the old ids are left as they were
    expect(into.x).toBe(x);
    expectSameBodies(into, 0, w.bodies());
  });

  it("gives new ids and new arrays, each exactly count long, when the count changes", () => {
    const w = row();
    const into = w.bodyArrays();
    const { ids, x, mu } = into;
    w.addBody("e", { x: 0, y: 8, r: 1, m: 1 });
    w.bodyArrays(0, into);
    expect(into.ids).not.toBe(ids);
    expect(into.x).not.toBe(x);
    expect(into.mu).not.toBe(mu);
    expect(x.length).toBe(3);
    expectSameBodies(into, 0, w.bodies());
    w.removeBody("a");
    w.removeBody("b");
    expectSameBodies(w.bodyArrays(0, into), 0, w.bodies());
    expect(into.count).toBe(2);
  });

  it("reuses a typed array of the new length and replaces one of another length, field by field", () => {
    const w = row();
    const into = w.bodyArrays();
    const y = into.y;
    into.r = new Float64Array(7);
    w.bodyArrays(0, into);
    expect(into.y).toBe(y);
    expect(into.r.length).toBe(3);
    expectSameBodies(into, 0, w.bodies());
  });

  it("follows a body re-added under its old id in another slot, and a clone reads the same", () => {
    const w = row();
    const into = w.bodyArrays();
    w.removeBody("a");
    w.addBody("f", { x: -10, y: 5, r: 1, m: 1 }); // takes a's slot
    w.addBody("a", { x: -10, y: -5, r: 1, m: 3 }); // a new slot
    expectSameBodies(w.bodyArrays(0, into), 0, w.bodies());
    expectSameBodies(w.clone().bodyArrays(), 0, w.bodies());
    // a caller writing into a handed-out ids array does not mislead the next read
    (into.ids as string[])[0] = "zz";
    expectSameBodies(w.bodyArrays(0), 0, w.bodies());
  });

  it("reads an empty World as count 0", () => {
    const a = new World().bodyArrays();
    expect(a.count).toBe(0);
    expect(a.ids).toStrictEqual([]);
    expect(a.x.length).toBe(0);
  });
});

describe("World.bodyArrays refuses what bodies(t) refuses, and a bad `into`", () => {
  it("throws bodies(t)'s ChapgameError for a bad t, writing nothing", () => {
    const ahead = row(); // not advanced: the contact at t = 2 is not processed yet
    const advanced = row();
    advanced.advance({ untilTime: 3 }); // b and c collided at t = 2: their motions start there
    const bad: [World, number][] = [
      [ahead, 10],
      [ahead, Number.NaN],
      [ahead, Number.POSITIVE_INFINITY],
      [ahead, "1" as unknown as number],
      [advanced, 1],
      [advanced, -1],
    ];
    for (const [w, t] of bad) {
      const into = w.bodyArrays();
      const snapshot = ARRAY_FIELDS.map((f) => Array.from(into[f]));
      let expected: unknown;
      try {
        w.bodies(t);
      } catch (e) {
        expected = e;
      }
      expect(expected, `t = ${t}`).toBeInstanceOf(ChapgameError);
      expect(() => w.bodyArrays(t, into)).toThrow(expected as ChapgameError);
      expect(() => w.bodyArrays(t, into)).toThrow(ChapgameError);
      expect(ARRAY_FIELDS.map((f) => Array.from(into[f]))).toStrictEqual(snapshot);
      expect(into.time).toBe(w.time);
    }
  });

  it("throws ChapgameError naming `into` for something that is not a previous result", () => {
    const w = row();
    const bad = [null, 3, "x", {}, { ...w.bodyArrays(), ids: "abc" }, { ...w.bodyArrays(), vy: [0, 0, 0] }];
    for (const into of bad) {
      const read = () => w.bodyArrays(0, into as unknown as BodyArrays);
      expect(read).toThrow(ChapgameError);
      expect(read).toThrow(/^into: must be a previous result/);
    }
  });
});

describe("World.bodyArrays property", () => {
  it("equals bodies(t) bit for bit on random scenes, at and between events, fresh or into the last result", () => {
    const caseArb = fc.record({
      bodies: fc.array(fc.record({ r: num(0.3, 1.2), vx: speed, vy: speed, m: num(0.5, 5) }), {
        minLength: 1,
        maxLength: 10,
      }),
      friction: fc.boolean(),
      mu: num(0.05, 1),
      gravity: fc.tuple(speed, speed),
      steps: fc.array(
        fc.record({ events: fc.integer({ min: 1, max: 6 }), frac: num(0, 1), remove: fc.nat() }),
        {
          minLength: 1,
          maxLength: 8,
        },
      ),
    });
    let read = 0;
    fc.assert(
      fc.property(caseArb, (c) => {
        const w = new World({ g: c.friction ? 5 : 0, gravity: c.friction ? [0, 0] : c.gravity });
        w.addLine("floor", [0, 0], [20, 0], "segment");
        w.addLine("wall", [20, 0], [20, 20], "line");
        w.addLine("ray", [0, 20], [0, 19], "ray");
        w.addPoint("pin", [10, 10]);
        c.bodies.forEach((b, i) => {
          const init = { x: 2.5 + 5 * (i % 4), y: 2.5 + 5 * Math.floor(i / 4), r: b.r, m: b.m };
          w.addBody(`b${i}`, { ...init, vx: b.vx, vy: b.vy, mu: c.friction ? c.mu : 0 });
        });
        let into: BodyArrays | undefined;
        const check = (t: number) => {
          const bodies = w.bodies(t);
          expectSameBodies(w.bodyArrays(t), t, bodies);
          into = w.bodyArrays(t, into);
          expectSameBodies(into, t, bodies);
          read++;
        };
        for (const s of c.steps) {
          try {
            w.advance({ maxEvents: s.events, untilTime: w.time + 5 });
          } catch (e) {
            if (!(e instanceof SimulationError)) throw e;
            return; // a Zeno state: states up to it were checked
          }
          check(w.time);
          // up to the next event, itself included (a friction stop there: velocity 0, no acceleration)
          let next: number;
          try {
            next = w.nextEventTime();
          } catch (e) {
            if (!(e instanceof SimulationError)) throw e;
            next = e.time; // states hold up to it
          }
          check(next < Number.POSITIVE_INFINITY ? next : w.time + s.frac);
          check(w.time + s.frac * (Math.min(next, w.time + 1) - w.time));
          const ids = [...into!.ids];
          if (ids.length > 1 && s.remove % 3 === 0) w.removeBody(ids[s.remove % ids.length] as string);
        }
      }),
      { seed: seedFor("World.bodyArrays"), numRuns: RUNS, verbose: true },
    );
    expect(read).toBeGreaterThan(RUNS * 3);
  });
});
