/**
 * Timing helpers: a monotonic clock in nanoseconds, medians and quantiles, "warm up then take the
 * median of several runs", and a description of the machine to print beside every number.
 * Timings are benchmark output only; nothing here is used by tests.
 */
import os from "node:os";

/** Monotonic time in nanoseconds as a double (precision is ample for runs under a few hours). */
export const nowNs = () => Number(process.hrtime.bigint());

export function quantile(values, q) {
  if (values.length === 0) return Number.NaN;
  const s = [...values].sort((a, b) => a - b);
  const pos = (s.length - 1) * q;
  const lo = Math.floor(pos);
  const hi = Math.ceil(pos);
  return s[lo] + (s[hi] - s[lo]) * (pos - lo);
}

export const median = (values) => quantile(values, 0.5);

/**
 * Run fn() `warmup` times untimed, then `runs` times timed. fn may return a number of nanoseconds it
 * measured itself (to exclude setup); otherwise the whole call is timed.
 * Returns { medianNs, minNs, maxNs, runs: [ns...] }.
 */
export function measure(fn, { warmup = 1, runs = 5 } = {}) {
  for (let i = 0; i < warmup; i++) fn();
  const times = [];
  for (let i = 0; i < runs; i++) {
    const t0 = nowNs();
    const own = fn();
    const t1 = nowNs();
    times.push(typeof own === "number" ? own : t1 - t0);
  }
  return { medianNs: median(times), minNs: Math.min(...times), maxNs: Math.max(...times), runs: times };
}

export function machine() {
  const cpus = os.cpus();
  return {
    cpu: cpus[0]?.model ?? "unknown",
    cores: cpus.length,
    memoryGiB: Math.round((os.totalmem() / 2 ** 30) * 10) / 10,
    platform: `${os.type()} ${os.release()} ${os.arch()}`,
    node: process.version,
    v8: process.versions.v8,
  };
}

/** Force a garbage collection when node runs with --expose-gc (bench/run.mjs re-executes itself so). */
export function gc() {
  if (typeof globalThis.gc === "function") globalThis.gc();
}

/**
 * Median of up to `runs` timed calls of fn() (each returns its own measured nanoseconds), stopping
 * early once `budgetNs` is spent (always at least one). The caller has already warmed up.
 */
export function timedRuns(fn, { runs = 3, budgetNs = 3e9 } = {}) {
  const times = [];
  let spent = 0;
  while (times.length < runs && (times.length === 0 || spent < budgetNs)) {
    const ns = fn();
    times.push(ns);
    spent += ns;
  }
  return { medianNs: median(times), runs: times.length, allNs: times };
}
