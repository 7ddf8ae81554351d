// The quartic crossing's zero-slope case: a root where the gap's derivative vanishes counts as a
// contact when the gap is negative just after it. After the last root that was probed at r + 1,
// which has a unit of time and equals r beyond 2^53 (review of the scale audit).
import { describe, expect, it } from "vitest";
import { firstDownCrossingQuartic } from "./quarticCrossing.js";

const INF = Number.POSITIVE_INFINITY;

describe("firstDownCrossingQuartic: a last root with zero slope", () => {
  it("-(t - r)^3 crosses down at r, for r at any scale (r = 2^54 was missed: r + 1 === r)", () => {
    for (const e of [-20, 0, 20, 54, 80]) {
      const r = 2 ** e;
      // -(t - r)^3 = r^3 - 3 r^2 t + 3 r t^2 - t^3, exact in doubles for a power of two r.
      expect(firstDownCrossingQuartic(r ** 3, -3 * r * r, 3 * r, -1, 0, 0, INF), `r = 2^${e}`).toBe(r);
      // (t - r)^3 crosses upwards there: no contact.
      expect(firstDownCrossingQuartic(-(r ** 3), 3 * r * r, -3 * r, 1, 0, 0, INF), `r = 2^${e} up`).toBe(INF);
    }
  });
});
