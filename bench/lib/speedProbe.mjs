/**
 * Machine speed probe: two fixed workloads timed in a fresh Node process, run before each section
 * of a benchmark and after the last, so the report can say whether the machine's speed held during
 * the run. This machine is a shared VM whose speed drifts by 20–150 % for minutes at a time, and the
 * guest sees no steal time (/proc/stat) that would show it.
 *
 * - `walk` looks like the engine's event loop to the CPU: a dependent walk through a 512 KB
 *   Float64Array (it fits in L2/L3, as a gas of 10³ discs does) with a data-dependent branch at
 *   every step.
 * - `fp` looks like the root solver: polynomial evaluations by Horner's rule, a square root, a
 *   division and branches on signs.
 * The slow spells here slow the two by different amounts, so both are kept. Each is deterministic
 * (the same instructions every time), so its time changes only with the machine. Result:
 * nanoseconds per step, the median of 7 timed repeats after 2 warm-ups, in a process that loads
 * nothing else (about 0.5 s for both).
 *
 * Run directly (`node bench/lib/speedProbe.mjs`) it prints one probe as JSON: a quick check of the
 * machine before starting a full benchmark.
 */
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";

const SIZE = 1 << 16;
const STEPS = 2_000_000;
const FP_STEPS = 4_000_000;
const WARMUP = 2;
const REPEATS = 7;

/** What the probe does, for the report. */
export const PROBE_WORKLOAD = `walk: ${STEPS.toLocaleString("en-US")} dependent steps through a ${(SIZE * 8) / 1024} KB Float64Array with a data-dependent branch each; fp: ${FP_STEPS.toLocaleString("en-US")} steps of two Horner evaluations, a square root or a division and two sign branches; each the median of ${REPEATS} repeats in a fresh process (bench/lib/speedProbe.mjs)`;

function table() {
  const a = new Float64Array(SIZE);
  let s = 12345;
  for (let i = 0; i < SIZE; i++) {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    a[i] = s / 4294967296;
  }
  return a;
}

function walk(a) {
  let acc = 0;
  let j = 0;
  for (let k = 0; k < STEPS; k++) {
    const x = a[j];
    if (x < 0.5) acc += x * 1.0000001;
    else acc -= x * 0.9999999;
    j = (j + ((x * 1024) | 0) + 1) & (SIZE - 1);
  }
  return acc;
}

function fp() {
  let s0 = 0;
  let s1 = 0;
  let x = 0.1;
  for (let k = 0; k < FP_STEPS; k++) {
    x += 1e-7;
    const p = (((1.5 * x - 2.25) * x + 0.75) * x - 0.125) * x + 0.0625;
    if (p > 0) s0 += Math.sqrt(p);
    else s1 -= p;
    const q = ((x * 0.5 + 1.25) * x - 3) * x + 0.5;
    if (q < 0.3) s1 += q * q;
    else s0 += 1 / q;
  }
  return s0 + s1;
}

/** Median ns per step of `run` (which does `steps` steps), after warm-ups. */
function timeKernel(run, steps) {
  let sink = 0;
  for (let i = 0; i < WARMUP; i++) sink += run();
  const ns = [];
  for (let i = 0; i < REPEATS; i++) {
    const t0 = process.hrtime.bigint();
    sink += run();
    ns.push(Number(process.hrtime.bigint() - t0) / steps);
  }
  if (Number.isNaN(sink)) throw new Error("speed probe: a workload produced NaN");
  return [...ns].sort((x, y) => x - y)[REPEATS >> 1];
}

/** One probe in this process: ns per step of each workload (medians). */
export function probeHere() {
  const a = table();
  return { walkNs: timeKernel(() => walk(a), STEPS), fpNs: timeKernel(fp, FP_STEPS) };
}

/** One probe in a fresh Node process (nothing else loaded); `at` labels when it was taken. */
export function probeSpeed(at) {
  const out = execFileSync(process.execPath, [fileURLToPath(import.meta.url)], { encoding: "utf8" });
  return { at, ...JSON.parse(out) };
}

/**
 * Summary of a run's probes: the fastest and slowest of each workload, and the spread (slowest /
 * fastest − 1). Back-to-back probes on this machine, with nothing else running, already differ by
 * up to about 15 % (its speed jitters from second to second), so a spread above SPREAD_WARN marks a
 * slow spell beyond that jitter: the run's absolute times are then suspect. A run that is slow
 * throughout shows no spread; its probe values, compared with another run's, show it.
 */
export const SPREAD_WARN = 0.25;

/**
 * Waiting out a slow spell (full runs): a probe before a section that is more than SLOW_BY slower
 * than the fastest probe of the run so far (either workload) makes the run wait WAIT_STEP_S and
 * probe again, until the speed is back or WAIT_MAX_S have been spent waiting in the whole run
 * (then it measures anyway, and the report says so). SLOW_BY sits above the ~15 % second-to-second
 * jitter, so a machine at its normal speed is never kept waiting; a run that starts in a slow spell
 * has nothing faster to compare with, and only the spread check shows it.
 */
export const SLOW_BY = 0.18;
export const WAIT_STEP_S = 30;
export const WAIT_MAX_S = 600;

/** Whether probe `p` is more than SLOW_BY slower than the fastest of `earlier` in either workload. */
export function slowerThanEarlier(p, earlier) {
  if (earlier.length === 0) return false;
  const fastest = (key) => Math.min(...earlier.map((q) => q[key]));
  return p.walkNs > (1 + SLOW_BY) * fastest("walkNs") || p.fpNs > (1 + SLOW_BY) * fastest("fpNs");
}

/**
 * Probes before a section, waiting out a slow spell as described at SLOW_BY: returns the probe to
 * keep and, when it waited, { before, seconds, slowProbes, gaveUp }. `spentS` is the waiting done
 * earlier in the run; `probe` and `sleepS` are injected (the tests pass fakes).
 */
export async function probeWhenSteady(at, earlier, spentS, { probe = probeSpeed, sleepS, log = () => {} }) {
  let p = probe(at);
  const slowProbes = [];
  let seconds = 0;
  while (slowerThanEarlier(p, earlier) && spentS + seconds < WAIT_MAX_S) {
    slowProbes.push(p);
    const step = Math.min(WAIT_STEP_S, WAIT_MAX_S - spentS - seconds);
    log(
      `   speed probe ${at}: walk ${p.walkNs.toFixed(2)} ns, fp ${p.fpNs.toFixed(2)} ns: over ${Math.round(100 * SLOW_BY)} % slower than earlier in the run; waiting ${step} s`,
    );
    await sleepS(step);
    seconds += step;
    p = probe(at);
  }
  if (slowProbes.length === 0) return { probe: p, wait: null };
  return { probe: p, wait: { before: at, seconds, slowProbes, gaveUp: slowerThanEarlier(p, earlier) } };
}

export function summarizeProbes(probes, waits = []) {
  const range = (key) => {
    const v = probes.map((p) => p[key]);
    const min = Math.min(...v);
    const max = Math.max(...v);
    return { minNs: min, maxNs: max, spread: max / min - 1 };
  };
  const walk = range("walkNs");
  const fp = range("fpNs");
  const spread = Math.max(walk.spread, fp.spread);
  return {
    workload: PROBE_WORKLOAD,
    probes,
    walk,
    fp,
    spread,
    warnAbove: SPREAD_WARN,
    steady: spread <= SPREAD_WARN,
    waits,
    slowBy: SLOW_BY,
  };
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  console.log(JSON.stringify(probeHere()));
}
