import { describe, expect, it } from "vitest";
import { axisExit } from "./cellExit.js";

const side = new Float64Array(1);
const INF = Number.POSITIVE_INFINITY;

describe("axisExit", () => {
  it("uniform motion leaves through the end ahead, at the exact division", () => {
    expect(axisExit(1, 2, 0, 0, INF, 0, 4, side)).toBe(1.5);
    expect(side[0]).toBe(1);
    expect(axisExit(1, -4, 0, 0, INF, 0, 4, side)).toBe(0.25);
    expect(side[0]).toBe(-1);
  });

  it("never leaves through an infinite end, nor when at rest", () => {
    expect(axisExit(1, 2, 0, 0, INF, 0, INF, side)).toBe(INF);
    expect(side[0]).toBe(0);
    expect(axisExit(1, 0, 0, 0, INF, 0, 4, side)).toBe(INF);
  });

  it("a centre already past the end by round-off, moving out, leaves now", () => {
    expect(axisExit(4 + 1e-15, 1, 0, 0.5, INF, 0, 4, side)).toBe(0.5);
    expect(side[0]).toBe(1);
  });

  it("under an acceleration the centre can turn back and leave through the end behind it", () => {
    // Thrown up at 1 from 0.5 in [0, 4] with acceleration -2: peak 0.75, back at 0 at tau = 1 + sqrt(1.5)/... solve 0.5 + t - t^2 = 0
    const t = axisExit(0.5, 1, -1, 0, INF, 0, 4, side);
    expect(side[0]).toBe(-1);
    expect(0.5 + t - t * t).toBeCloseTo(0, 14);
    expect(t).toBeCloseTo((1 + Math.sqrt(3)) / 2, 14);
  });

  it("decelerating motion that stops inside the cell never leaves (window ends at the stop)", () => {
    // v = 1, a = -1 (ha = -0.5): stops at tau = 1 after 0.5; the upper end at 1 is never reached.
    expect(axisExit(0.25, 1, -0.5, 0, 1, 0, 1, side)).toBe(INF);
  });
});
