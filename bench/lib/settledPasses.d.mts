/** Types of bench/lib/settledPasses.mjs (the side-by-side rows' warm-up and timed passes), for the tests. */
export interface PassLimits {
  warmupBudgetNs: number;
  maxWarmup: number;
  ownWarmupNs: number;
  settleWindow: number;
  settleWithin: number;
  minRuns: number;
  maxRuns: number;
  softBudgetNs: number;
  hardBudgetNs: number;
}
export interface Spread {
  medianNs: number;
  minNs: number;
  q1Ns: number;
  q3Ns: number;
  maxNs: number;
}
export interface SettledPasses extends Spread {
  runs: number;
  allNs: number[];
  /** settled: null when the caller's own pass was long enough to be the warm-up (no warm-up pass ran). */
  warmup: { passes: number; allNs: number[]; settled: boolean | null };
}
export const PASS_LIMITS: PassLimits;
export function isSettled(
  times: number[],
  limits?: Pick<PassLimits, "settleWindow" | "settleWithin">,
): boolean;
export function spreadOf(times: number[]): Spread;
export function settledPasses(
  pass: () => number,
  options?: { alreadyNs?: number; limits?: PassLimits },
): SettledPasses;
