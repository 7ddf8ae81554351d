/**
 * Arithmetic nextUp/nextDown for the quartic hot path (no typed-array round trip for normal
 * magnitudes).
 *
 * `nextUp(x)` / `nextDown(x)`: the adjacent double above / below a finite x. For
 * 2^-960 ≤ |x| < 2^1023 it is x ± |x|·(2^-53 + 2^-105) in round-to-nearest (the addend lies strictly
 * between half an ulp and 1.5 ulps of x, also at binade ends; checked against exactPoly.ts's bit
 * version in nextDouble.test.ts); else exactPoly.ts's bit version.
 */

import { nextUp as nextUpBits } from "./exactPoly.js";

const NEXT = 2 ** -53 + 2 ** -105;
const NEXT_MIN = 2 ** -960;
const NEXT_MAX = 2 ** 1023;

/** The adjacent double above a finite x. */
export function nextUp(x: number): number {
  const ax = Math.abs(x);
  return ax >= NEXT_MIN && ax < NEXT_MAX ? x + ax * NEXT : nextUpBits(x);
}

/** The adjacent double below a finite x. */
export function nextDown(x: number): number {
  const ax = Math.abs(x);
  return ax >= NEXT_MIN && ax < NEXT_MAX ? x - ax * NEXT : -nextUpBits(-x);
}
