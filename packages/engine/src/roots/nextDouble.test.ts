import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { nextDown, nextUp } from "./exactPoly.js";
import { nextDown as fastNextDown, nextUp as fastNextUp } from "./nextDouble.js";
import { fcParams } from "./testSupport.js";

const params = fcParams("nextDouble.test", 400);

describe("nextDouble (the quartic hot path's nextUp/nextDown)", () => {
  it("arithmetic nextUp/nextDown equal the bit-pattern ones (binade ends, signs, tiny and huge)", () => {
    const special = [
      1,
      2,
      0.5,
      2 ** -960,
      2 ** -1022,
      2 ** 1022,
      1 - 2 ** -53,
      2 - 2 ** -52,
      5e-324,
      0,
      1e300,
    ];
    for (const x of special) {
      for (const y of [x, -x, nextUp(x), nextDown(x), -nextUp(x)]) {
        expect(fastNextUp(y)).toBe(nextUp(y));
        expect(fastNextDown(y)).toBe(nextDown(y));
      }
    }
    fc.assert(
      fc.property(fc.double({ noNaN: true, noDefaultInfinity: true }), (x) => {
        if (Math.abs(x) === Number.MAX_VALUE) return true; // its nextUp is Infinity: never a bracket end
        expect(fastNextUp(x)).toBe(nextUp(x));
        expect(fastNextDown(x)).toBe(nextDown(x));
        return true;
      }),
      params,
    );
  });
});
