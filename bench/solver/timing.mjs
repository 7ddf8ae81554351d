/**
 * Timing of the solver section, in fresh child processes that load only the engine and the solver
 * benchmark's own modules.
 *
 * Why child processes: the time per call of a few-hundred-nanosecond function depends on the
 * process it runs in, not only on its code. In the benchmark's main process, which has loaded every
 * section's modules (matter-js, planck, rapier, the WebAssembly gas loop), the same harness measured
 * realRoots about 25 % slower and the bisection baseline about 10 % slower than in a process that
 * loaded only the solver's modules (perf stat: the same instructions, more cycles, branch and TLB
 * misses: code and data placement). A fresh process per measurement, taken `processes` times, and
 * the median over them, measures the code rather than one process's placement; the per-process
 * values are reported so that the spread is visible.
 *
 * `timeSolvers({ quick, processes })` → { random: {id: ns}, hard: {id: ns}, perProcess: [...] }.
 * Run as a script (`node timing.mjs quick`), it measures once and prints one JSON line.
 */
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { loadEngine } from "../lib/engine.mjs";
import { median, nowNs } from "../lib/timing.mjs";
import { bisection, ferrari, ferrariNewton } from "./methods.mjs";
import { collisionQuartics, hardQuartics } from "./quartics.mjs";

export function methods(engine) {
  return [
    { id: "realRoots", label: "realRoots (engine)", fn: engine.realRoots },
    { id: "ferrari", label: "Ferrari closed form", fn: ferrari },
    { id: "ferrariNewton", label: "Ferrari + 2 Newton steps", fn: ferrariNewton },
    { id: "bisection", label: "seed bisection, eps 1e-6", fn: bisection },
  ];
}

/**
 * ns per call of every method over a set of polynomials: the methods are timed round-robin (one
 * pass each, `runs` rounds, after two warm-up rounds) so that load from other processes hits them
 * alike; the median pass time per method / calls per pass.
 */
function interleaved(ms, items, runs, calls) {
  const reps = Math.max(1, Math.round(calls / items.length));
  const times = ms.map(() => []);
  let sink = 0;
  for (let round = -2; round < runs; round++) {
    ms.forEach((m, i) => {
      const a = nowNs();
      for (let r = 0; r < reps; r++) for (const it of items) sink += m.fn(it.c, it.lo, it.hi).length;
      if (round >= 0) times[i].push(nowNs() - a);
    });
  }
  if (sink < 0) throw new Error("unreachable: root counts are never negative");
  return times.map((t) => median(t) / (reps * items.length));
}

/** One measurement in this process: ns per call by method id, random set and hard set. */
async function measureHere(quick) {
  const { engine } = await loadEngine();
  const ms = methods(engine);
  const runs = quick ? 5 : 9;
  const { polys, lo, hi } = collisionQuartics(quick ? 300 : 4000, 7);
  const random = interleaved(
    ms,
    polys.map((c) => ({ c, lo, hi })),
    runs,
    quick ? 30000 : 200000,
  );
  const hardItems = hardQuartics().map((h) => ({ c: h.coeffs, lo: h.lo, hi: h.hi }));
  const hard = interleaved(ms, hardItems, runs, quick ? 10000 : 50000);
  const byId = (ns) => Object.fromEntries(ms.map((m, i) => [m.id, ns[i]]));
  return { random: byId(random), hard: byId(hard) };
}

function measureInChild(quick) {
  const out = execFileSync(process.execPath, [fileURLToPath(import.meta.url), quick ? "quick" : "full"], {
    encoding: "utf8",
    maxBuffer: 1 << 20,
  });
  return JSON.parse(out.trim().split("\n").pop());
}

export function timeSolvers({ quick, processes }) {
  const perProcess = [];
  for (let i = 0; i < processes; i++) perProcess.push(measureInChild(quick));
  const pick = (set) =>
    Object.fromEntries(
      Object.keys(perProcess[0][set]).map((id) => [id, median(perProcess.map((p) => p[set][id]))]),
    );
  return { random: pick("random"), hard: pick("hard"), perProcess };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  console.log(JSON.stringify(await measureHere(process.argv[2] === "quick")));
}
