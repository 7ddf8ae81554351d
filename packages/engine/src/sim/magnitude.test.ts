// Magnitudes: lengths and rates beyond MAGNITUDE_MAX, and radii below RADIUS_MIN, are refused
// naming the field (the contact polynomials would over- or underflow and a contact would be missed
// without a word); within the range, a head-on pair collides at its exact time at every scale.
import { describe, expect, it } from "vitest";
import { FIELD_MIN, MAGNITUDE_MAX, RADIUS_MIN } from "../tolerances.js";
import { ChapgameError } from "./errors.js";
import { World } from "./world.js";

/** Two discs of radius s/10 at -s/2 and s/2 closing at s/5: contact at t = 4. */
function headOn(s: number): World {
  const w = new World({ g: 0 });
  w.addBody("a", { x: -0.5 * s, y: 0, r: 0.1 * s, m: 1, vx: 0.1 * s });
  w.addBody("b", { x: 0.5 * s, y: 0, r: 0.1 * s, m: 1, vx: -0.1 * s });
  return w;
}

describe("magnitudes", () => {
  it("a head-on pair collides at t = 4 at every scale from 1e-29 to 1e30", () => {
    for (const s of [1e-29, 1e-10, 1, 1e10, MAGNITUDE_MAX]) {
      const w = headOn(s);
      const times: number[] = [];
      w.advance({ maxEvents: 5 }, (e) => times.push(e.time));
      expect({ s, times: times.length }).toEqual({ s, times: 1 });
      expect(Math.abs((times[0] as number) - 4)).toBeLessThanOrEqual(1e-12);
    }
  });

  it("refuses what would overflow or underflow, naming the field (the audit's silent misses)", () => {
    // These pairs used to give 0 events and no error: s = 1e77 and 1e-90, and v = 1e153 at unit size.
    expect(() => headOn(1e77)).toThrow(/^x: must be at most 1e\+30 in size/);
    expect(() => headOn(1e-90)).toThrow(/^r: must be between 1e-30 and 1e\+30/);
    const w = new World({ g: 0 });
    expect(() => w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1e153 })).toThrow(
      /^vx: must be at most 1e\+30/,
    );
    expect(w.bodies()).toEqual([]);
    const cases: [string, () => unknown][] = [
      ["y", () => w.addBody("b", { x: 0, y: -2e30, r: 1, m: 1 })],
      ["r", () => w.addBody("b", { x: 0, y: 0, r: 2e30, m: 1 })],
      ["r", () => w.addBody("b", { x: 0, y: 0, r: RADIUS_MIN / 2, m: 1 })],
      ["mu", () => w.addBody("b", { x: 0, y: 0, r: 1, m: 1, mu: 1e31 })],
      ["p1[0]", () => w.addLine("l", [-1e31, 0], [0, 0], "segment")],
      ["p[1]", () => w.addPoint("p", [0, 1e40])],
      ["g", () => w.setGlobal({ g: 1e31 })],
      ["gravity[1]", () => w.setGlobal({ gravity: [0, -1e31] })],
      ["g", () => new World({ g: 1e31 })],
    ];
    for (const [field, edit] of cases) {
      let err: unknown;
      try {
        edit();
      } catch (e) {
        err = e;
      }
      expect(err).toBeInstanceOf(ChapgameError);
      expect((err as Error).message.startsWith(`${field}: `)).toBe(true);
    }
    expect(w.bodies()).toEqual([]);
    expect(w.lines()).toEqual([]);
    expect(w.points()).toEqual([]);
    expect(w.g).toBe(0);
  });

  it("accepts the bounds themselves", () => {
    const w = new World({ g: MAGNITUDE_MAX });
    w.addBody("a", { x: MAGNITUDE_MAX, y: -MAGNITUDE_MAX, r: RADIUS_MIN, m: 1, vx: MAGNITUDE_MAX, mu: 1 });
    w.addBody("b", { x: 0, y: 0, r: MAGNITUDE_MAX / 4, m: 1 });
    w.addPoint("p", [MAGNITUDE_MAX, MAGNITUDE_MAX]);
    expect(w.bodies().length).toBe(2);
  });

  it("refuses speeds too small to square (1e-170 underflowed: the pair passed through), accepts 0", () => {
    const w = new World({ g: 0 });
    expect(() => w.addBody("a", { x: -1.5, y: 0, r: 1, m: 1, vx: 1e-170 })).toThrow(
      /^vx: must be 0 or at least 1e-30/,
    );
    w.addBody("a", { x: -1.5, y: 0, r: 1, m: 1, vx: 0 });
    expect(() => w.updateBody("a", { vy: -1e-40 })).toThrow(/^vy: must be 0 or at least 1e-30/);
    expect(w.body("a").vy).toBe(0);
  });

  it("refuses fields too small to square (gravity 1e-200: a point 'touched' 0.67 radii away; review), accepts 0 and FIELD_MIN", () => {
    expect(() => new World({ g: 0, gravity: [0, -1e-200] })).toThrow(
      /^gravity\[1\]: must be 0 or at least 1e-30/,
    );
    expect(() => new World({ g: 1e-31 })).toThrow(/^g: must be 0 or at least 1e-30/);
    const w = new World({ g: FIELD_MIN, gravity: [0, 0] });
    expect(() => w.addBody("a", { x: 0, y: 0, r: 1, m: 1, mu: 1e-200 })).toThrow(
      /^mu: must be 0 or at least 1e-30/,
    );
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, mu: FIELD_MIN, vx: 1 });
    expect(() => w.updateBody("a", { mu: 5e-324 })).toThrow(/^mu: must be 0 or at least 1e-30/);
    expect(() => w.setGlobal({ g: 0, gravity: [-1e-40, 0] })).toThrow(
      /^gravity\[0\]: must be 0 or at least 1e-30/,
    );
    expect(w.g).toBe(FIELD_MIN);
    expect(w.body("a").mu).toBe(FIELD_MIN);
    // At the bound itself a drop onto a point is found where the disc touches it.
    const d = new World({ g: 0, gravity: [0, -FIELD_MIN] });
    d.addPoint("p", [0, 0]);
    d.addBody("b", { x: 0, y: 3, r: 1, m: 1 });
    const times: number[] = [];
    d.advance({ maxEvents: 1 }, (e) => times.push(e.time));
    expect(times.length).toBe(1);
    expect(Math.abs(d.body("b", times[0]).y - 1)).toBeLessThan(1e-9);
  });

  it("a state the World reached beyond the bounds (gravity 1e30) can still be edited and rebuilt", () => {
    const w = new World({ g: 0, gravity: [0, -MAGNITUDE_MAX] });
    w.addBody("f", { x: 0, y: 0, r: 1, m: 1 });
    w.advance({ untilTime: 2 });
    expect(w.body("f").vy).toBe(-2 * MAGNITUDE_MAX);
    w.updateBody("f", { m: 3 }); // only the patched field is held to the edit bounds
    expect(w.body("f").m).toBe(3);
    const m = w.motion("f");
    const copy = new World({ g: 0, gravity: [0, -MAGNITUDE_MAX], time: 3 });
    copy.addBodyMotion("f", { t0: m.t0, x0: m.x0, y0: m.y0, vx: m.vx, vy: m.vy, r: 1, m: 3, mu: 0 });
    expect(copy.body("f", 3)).toStrictEqual(w.body("f", 3));
  });

  it("a disc flying 1e8 contact distances to a resting one hits it (review: it flew through, grid on or off)", () => {
    for (const broadPhase of [true, false]) {
      const w = new World({ g: 0, optimizations: { broadPhase } });
      w.addBody("a", { x: 0, y: 0, r: 0.5, m: 1, vx: 1 });
      w.addBody("b", { x: 1e8, y: 0, r: 0.5, m: 1 });
      const times: number[] = [];
      w.advance({ untilTime: 2e8 }, (e) => times.push(e.time));
      expect(times.length).toBe(1);
      expect(Math.abs((times[0] as number) - (1e8 - 1))).toBeLessThanOrEqual(1e-7);
      expect(w.body("b", 2e8).x).toBeCloseTo(2e8 + 1, 6); // b takes a's speed at t = 1e8 - 1
    }
  });
});
