/**
 * Shared setup of the roots tests (test-only; not part of the engine's API).
 *
 * - `fcParams(name, runs)`: fast-check parameters with one seed per test file and run, printed so
 *   that a failure can be replayed (`FC_SEED=<seed>`; `FC_RUNS` overrides the number of runs).
 * - `num(min, max)`: finite doubles in [min, max] (no NaN, no infinities).
 * - `fromRoots(roots, lead = 1)`: ascending coefficients of lead·∏(t − rᵢ), expanded in double
 *   arithmetic (exact when the roots have few mantissa bits).
 * - `expectVerified(c, lo, hi, roots, samples, label)`: asserts verifyRoots's contract for a root
 *   list: ordered, every root within 4 ulps of an exact root, no exact sign change missed between
 *   the samples; grazing (double-root) reports are accepted under their own contract
 *   (isGrazingRoot) when `grazingOk`.
 * - `expectCertified(c, lo, hi, samples = 64)`: realRoots(c, lo, hi), asserted as expectVerified
 *   does (no grazing reports accepted), and returned.
 */

import fc from "fast-check";
import { expect } from "vitest";
import { realRoots } from "./realRoots.js";
import { isGrazingRoot, verifyRoots } from "./verifyRoots.js";

/** The test runner's process environment and console (the engine's build has neither Node nor DOM types). */
const host = globalThis as {
  process?: { env: Record<string, string | undefined> };
  console?: { log(message: string): void };
};
const env = host.process?.env ?? {};

export function fcParams(name: string, runs: number) {
  const seed = Number(env.FC_SEED ?? Math.floor(Math.random() * 2 ** 31));
  host.console?.log(`${name} seed: ${seed} (replay with FC_SEED=${seed})`);
  return { seed, numRuns: Number(env.FC_RUNS ?? runs), verbose: true } as const;
}

export const num = (min: number, max: number) =>
  fc.double({ min, max, noNaN: true, noDefaultInfinity: true });

export function fromRoots(roots: readonly number[], lead = 1): number[] {
  let c = [lead];
  for (const r of roots) {
    const n: number[] = new Array(c.length + 1).fill(0);
    for (let i = 0; i < c.length; i++) {
      n[i + 1] = (n[i + 1] as number) + (c[i] as number);
      n[i] = (n[i] as number) - r * (c[i] as number);
    }
    c = n;
  }
  return c;
}

export function expectVerified(
  c: readonly number[],
  lo: number,
  hi: number,
  roots: readonly number[],
  samples: number,
  grazingOk = false,
): void {
  const check = verifyRoots(c, lo, hi, roots, samples, 4);
  const where = `roots ${roots} of ${c} on [${lo}, ${hi}]`;
  expect(check.ordered, `ordered: ${where}`).toBe(true);
  if (grazingOk && check.maxUlps > 4) {
    for (const r of roots) {
      if (verifyRoots(c, lo, hi, [r], 0, 4).maxUlps <= 4) continue;
      expect(isGrazingRoot(c, r), `root ${r}: ${where}`).toBe(true);
    }
  } else {
    expect(check.maxUlps, `worst root ${check.worst}: ${where}`).toBeLessThanOrEqual(4);
  }
  expect(check.missed, `missed sign changes: ${where}`).toEqual([]);
}

/** Every root within 4 ulps of an exact root, sorted, inside, and no exact sign change missed. */
export function expectCertified(c: readonly number[], lo: number, hi: number, samples = 64): number[] {
  const roots = realRoots(c, lo, hi);
  expectVerified(c, lo, hi, roots, samples);
  return roots;
}
