/**
 * The benchmark's polydisperse gases (bench/scenes/polydisperse.mjs): n discs of the law's radii,
 * inside the box, none overlapping, 10 % packing, the same scene for the same seed; an unknown law
 * is refused by name.
 */
import { describe, expect, it } from "vitest";
import { polydisperseGas, RADIUS_LAWS } from "../../bench/scenes/polydisperse.mjs";

describe("polydisperse gas scenes", () => {
  for (const law of Object.keys(RADIUS_LAWS)) {
    it(`${law}: 2,000 discs in the box, none overlapping, 10 % packing`, () => {
      const scene = polydisperseGas({ n: 2000, law });
      const side = scene.walls[1]?.p1[0] as number;
      expect(scene.bodies).toHaveLength(2000);
      let area = 0;
      for (const b of scene.bodies) {
        area += Math.PI * b.r * b.r;
        expect(b.x - b.r).toBeGreaterThan(0);
        expect(b.x + b.r).toBeLessThan(side);
        expect(b.y - b.r).toBeGreaterThan(0);
        expect(b.y + b.r).toBeLessThan(side);
      }
      expect(area / (side * side)).toBeCloseTo(0.1, 12);
      const sorted = [...scene.bodies].sort((a, b) => a.x - b.x);
      const rMax = Math.max(...sorted.map((b) => b.r));
      sorted.forEach((a, i) => {
        for (const b of sorted.slice(i + 1)) {
          if (b.x - a.x >= 2 * rMax) break;
          expect(Math.hypot(a.x - b.x, a.y - b.y)).toBeGreaterThan(a.r + b.r);
        }
      });
      expect(polydisperseGas({ n: 2000, law })).toEqual(scene);
    });
  }

  it("refuses an unknown radius law by name", () => {
    expect(() => polydisperseGas({ law: "r = 7" })).toThrow("unknown radius law 'r = 7'");
  });
});
