import { describe, expect, it } from "vitest";
import { World } from "../sim/world.js";
import { MASS_MAX } from "../tolerances.js";
import { discDiscResponse, impulseMagnitude, impulseShare } from "./response.js";

const INF = Number.POSITIVE_INFINITY;

describe("impulseShare and impulseMagnitude at the ends of the double range (audit: 1e200 gave Infinity, 1e-200 gave 0)", () => {
  it("keeps the textbook values for ordinary masses, bit for bit", () => {
    expect(impulseShare(1, 3)).toBe(1.5);
    expect(impulseShare(3, 1)).toBe(0.5);
    expect(impulseMagnitude(1, 3, 2)).toBe(3);
    expect(impulseMagnitude(2, 2, 1)).toBe(2);
    expect(impulseShare(INF, 1)).toBe(0);
    expect(impulseShare(1, INF)).toBe(2);
    expect(impulseShare(INF, INF)).toBe(1);
    expect(impulseMagnitude(INF, 5, 1)).toBe(10);
    expect(impulseMagnitude(INF, INF, 1)).toBe(INF);
    expect(impulseMagnitude(INF, INF, 0)).toBe(0);
  });

  it("reports the impulse of equal huge or tiny masses (2 m1 m2 / (m1 + m2) = m) instead of Infinity or 0", () => {
    for (const m of [1e200, 1e300, Number.MAX_VALUE, 1e-200, 1e-300]) {
      expect([m, impulseMagnitude(m, m, 1)]).toEqual([m, m]);
      expect([m, impulseShare(m, m)]).toEqual([m, 1]);
    }
    expect(impulseMagnitude(1e-200, 1e200, 1)).toBe(2e-200);
    expect(impulseMagnitude(1e200, 1e-200, 1)).toBe(2e-200);
  });

  it("gives finite shares (no NaN velocities) when 2 m or the sum of the masses overflows", () => {
    expect(impulseShare(1e308, 1e308)).toBe(1);
    expect((impulseShare(Number.MAX_VALUE, 1) * Number.MAX_VALUE) / 2).toBeCloseTo(1, 12); // 2 / (MAX + 1)
    expect(impulseShare(1, Number.MAX_VALUE)).toBe(2);
    expect(impulseShare(1e308, 1e307)).toBeCloseTo(2 / 11, 15);
    const out = new Float64Array(4);
    discDiscResponse(0, 0, 1, 0, 1e308, 2, 0, 0, 0, 1e308, out);
    expect([...out]).toEqual([0, 0, 1, 0]);
  });

  it("a World refuses mass 1e308 (beyond MASS_MAX: its impulse 2 m v overflowed); at MASS_MAX two discs swap velocities", () => {
    const w = new World({ g: 0 });
    expect(() => w.addBody("a", { x: 0, y: 0, r: 1, m: 1e308, vx: 1 })).toThrow(/^m: must be between/);
    w.addBody("a", { x: 0, y: 0, r: 1, m: MASS_MAX, vx: 1 });
    w.addBody("b", { x: 5, y: 0, r: 1, m: MASS_MAX });
    const impulses: number[] = [];
    w.advance({ untilTime: 10 }, (e) => impulses.push(e.impulse));
    expect(impulses.length).toBe(1);
    expect((impulses[0] as number) / MASS_MAX).toBeCloseTo(1, 14);
    expect([w.body("a").vx, w.body("b").vx]).toEqual([0, 1]);
  });
});
