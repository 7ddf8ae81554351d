import { describe, expect, it } from "vitest";
import { evalPoly, realRoots } from "./realRoots.js";

describe("realRoots", () => {
  it("finds the roots of a quartic product of linear factors", () => {
    // (t-1)(t-2)(t-3)(t-4) = 24 - 50t + 35t² - 10t³ + t⁴
    const r = realRoots([24, -50, 35, -10, 1], 0, 10);
    expect(r.length).toBe(4);
    for (const [i, x] of [1, 2, 3, 4].entries()) expect(r[i]).toBeCloseTo(x, 12);
  });
  it("evaluates by Horner", () => {
    expect(evalPoly([1, 2, 3], 2)).toBe(17);
  });
});
