/**
 * bernstein's quick checks on their own (they were tested only through realRoots: review of session
 * 20): no root where the polynomial keeps one sign, exactly one where it crosses once (with a guess
 * inside the interval), "unknown" where two roots or a near-double root make the signs uncertain,
 * and the derivative's count beside it.
 */
import { describe, expect, it } from "vitest";
import { bernstein, derivChanges, guesses } from "./bernstein.js";

/** bernstein on the polynomial with ascending coefficients `c` over [lo, hi]. */
function run(c: number[], lo: number, hi: number): { v: number; d: number; guess: number } {
  const p = Float64Array.from(c);
  const n = c.length - 1;
  const T = new Float64Array(n + 1);
  const A = new Float64Array(n + 1);
  const v = bernstein(p, n, lo, hi, T, A);
  return { v, d: derivChanges, guess: guesses[0] as number };
}

describe("bernstein", () => {
  it("one sign over the interval: no root (0); a check that cannot settle it says so (−1)", () => {
    expect(run([1, 0, 1], 0, 1).v).toBe(0); // 1 + t² on [0, 1]: coefficients 1, 1, 2
    expect(run([-5, 1], 0, 4).v).toBe(0); // t − 5 < 0 on [0, 4]
    expect(run([2, -3, 1], 3, 10).v).toBe(0); // (t − 1)(t − 2) > 0 beyond 2
    // 1 + t² on [−2, 2] is positive, but its coefficients there are 5, −3, 5: the quick check is
    // conservative and leaves it to the full method
    expect(run([1, 0, 1], -2, 2).v).toBe(-1);
  });

  it("one crossing: exactly one root (1), the guess inside the interval near it", () => {
    const r = run([-2, 0, 1], 0, 3); // t² − 2: root √2
    expect(r.v).toBe(1);
    expect(r.guess).toBeGreaterThan(0);
    expect(r.guess).toBeLessThan(3);
    expect(Math.abs(r.guess - Math.SQRT2)).toBeLessThan(1);
    // p′ = 2t is 0 at the interval's start: a zero coefficient, so its count is not certain
    expect(r.d).toBe(-1);
    const lin = run([-1, 2], 0, 1); // 2t − 1: root 1/2, and the control polygon crosses there
    expect(lin.v).toBe(1);
    expect(lin.guess).toBe(0.5);
  });

  it("two roots, or a double one: not settled by the quick check (−1)", () => {
    expect(run([2, -3, 1], 0, 3).v).toBe(-1); // roots 1 and 2
    expect(run([1, -2, 1], 0, 2).v).toBe(-1); // (t − 1)²: a double root
    expect(run([-2, 0, 1], 1, 2).v).toBe(-1); // t² − 2 on [1, 2]: a zero coefficient, uncertain
    const d = run([2, -3, 1], 0, 3).d; // p′ = 2t − 3 changes sign once on [0, 3]
    expect(d).toBe(1);
  });

  it("the same answers at any power-of-two scale of the variable", () => {
    for (const s of [2 ** -40, 1, 2 ** 40]) {
      // (t/s)² − 2 on [0, 3s], 1 + (t/s)² on [0, s]
      expect(run([-2, 0, 1 / (s * s)], 0, 3 * s).v).toBe(1);
      expect(run([1, 0, 1 / (s * s)], 0, s).v).toBe(0);
    }
  });
});
