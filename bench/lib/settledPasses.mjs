/**
 * Timing of one side-by-side row (bench/peers): warm-up passes until the times settle, then timed
 * passes, with their spread. settledPasses(pass, { alreadyNs, limits }) calls pass() (which returns
 * the nanoseconds it measured itself) and returns { medianNs, minNs, q1Ns, q3Ns, maxNs, runs, allNs,
 * warmup: { passes, allNs, settled } } (settled: true, false when a limit stopped the warm-up first,
 * null when no warm-up pass ran). The caller has already run one pass of its own (the metrics pass,
 * `alreadyNs` long; see ownWarmupNs) and must not force a garbage collection between that pass and
 * this call: a forced full collection deoptimises what the warm-up compiled (bench/README.md,
 * "Side-by-side timings"). The limits below bound the cost of a row.
 */
import { median, quantile } from "./timing.mjs";

export const PASS_LIMITS = {
  // Warm-up: passes of the timed function itself, stopped once the last settleWindow of them are
  // settled, or after warmupBudgetNs of them or maxWarmup passes. 0.25 s covers the gas rows'
  // tier-up at the load of a shared 2-core machine. The caller's metrics pass counts in that budget
  // only when it took ownWarmupNs or more: such a long pass stands for the warm-up (this bounds the
  // cost; a first timed pass left slower is one of at least three, and the spread shows it). A
  // shorter one, which calls the engine differently (chapgame's in 480 slices with reads between),
  // left the timed call's first passes 3 to 10x slow in our runs.
  warmupBudgetNs: 0.25e9,
  maxWarmup: 20,
  ownWarmupNs: 0.5e9,
  // Settled: the median of the last `settleWindow` warm-up passes within `settleWithin` (relative)
  // of the fastest warm-up pass. Passes of optimised code on this machine differ by up to about 2x
  // under load (the scheduler's slices), unoptimised ones are 5 to 20x slower: 0.2 tells them apart.
  settleWindow: 3,
  settleWithin: 0.2,
  // Timed passes: at least minRuns, then more while the timed passes have taken less than
  // softBudgetNs, at most maxRuns; never beyond hardBudgetNs (the first pass always runs).
  minRuns: 3,
  maxRuns: 15,
  softBudgetNs: 0.2e9,
  hardBudgetNs: 3e9,
};

/** True when the last `window` times are within `within` of the fastest of all of them. */
export function isSettled(times, { settleWindow, settleWithin } = PASS_LIMITS) {
  if (times.length < settleWindow) return false;
  const last = median(times.slice(-settleWindow));
  return last <= (1 + settleWithin) * Math.min(...times);
}

/** Quartiles and extremes of a list of nanosecond times (the timed passes). */
export function spreadOf(times) {
  return {
    medianNs: median(times),
    minNs: Math.min(...times),
    q1Ns: quantile(times, 0.25),
    q3Ns: quantile(times, 0.75),
    maxNs: Math.max(...times),
  };
}

export function settledPasses(pass, { alreadyNs = 0, limits = PASS_LIMITS } = {}) {
  const warm = [];
  let spent = alreadyNs >= limits.ownWarmupNs ? alreadyNs : 0;
  let settled = false;
  while (warm.length < limits.maxWarmup && spent < limits.warmupBudgetNs) {
    const ns = pass();
    warm.push(ns);
    spent += ns;
    if (isSettled(warm, limits)) {
      settled = true;
      break;
    }
  }
  const times = [];
  let timed = 0;
  const more = () =>
    times.length === 0 ||
    (times.length < limits.maxRuns &&
      timed < limits.hardBudgetNs &&
      (times.length < limits.minRuns || timed < limits.softBudgetNs));
  while (more()) {
    const ns = pass();
    times.push(ns);
    timed += ns;
  }
  // settled null: not checked, the caller's pass was long enough to be the warm-up.
  const warmup = { passes: warm.length, allNs: warm, settled: warm.length === 0 ? null : settled };
  return { ...spreadOf(times), runs: times.length, allNs: times, warmup };
}
