/**
 * `npm run bench [-- --quick] [-- --only=solver,peers,engine,stress] [-- --no-wait]`: runs the benchmark sections
 * against the BUILT engine, writes bench/results/latest.json (quick runs: bench/results/tmp/quick.json,
 * not committed), then generates docs/benchmarks.md, docs/benchmarks-headline.md and docs/bench/*.svg
 * (quick runs: the same files under bench/results/tmp/quick-report/, so the committed report stays full).
 * `--push-digits=N` instead runs only Galperin's billiard pushed to N digits with no time budget
 * (9 digits took 744 s) into bench/results/galperin-push.json, which the report merges.
 * Re-executes itself with --expose-gc so runs can collect garbage between measurements.
 * A full run probes the machine's speed before each section and waits out a slow spell
 * (bench/lib/speedProbe.mjs: SLOW_BY, at most WAIT_MAX_S in all); `--no-wait` measures at once.
 */
import { spawnSync } from "node:child_process";
import { mkdirSync, writeFileSync } from "node:fs";
import { dirname, join, relative } from "node:path";
import { fileURLToPath } from "node:url";

if (typeof globalThis.gc !== "function" && !process.env.CHAPGAME_BENCH_CHILD) {
  const r = spawnSync(
    process.execPath,
    ["--expose-gc", fileURLToPath(import.meta.url), ...process.argv.slice(2)],
    {
      stdio: "inherit",
      env: { ...process.env, CHAPGAME_BENCH_CHILD: "1" },
    },
  );
  process.exit(r.status ?? 1);
}

const { loadEngine } = await import("./lib/engine.mjs");
const { machine, nowNs } = await import("./lib/timing.mjs");
const { runSolver } = await import("./solver/run.mjs");
const { runPeers } = await import("./peers/run.mjs");
const { runEngine } = await import("./engine/run.mjs");
const { runStress } = await import("./stress/run.mjs");
const { generate } = await import("./report/generate.mjs");
const { probeWhenSteady, summarizeProbes } = await import("./lib/speedProbe.mjs");

const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..");
const args = process.argv.slice(2);
const quick = args.includes("--quick");
const onlyArg = args.find((a) => a.startsWith("--only="));
const only = onlyArg ? new Set(onlyArg.slice(7).split(",")) : null;
const want = (s) => !only || only.has(s);
const log = (m) => console.log(m);

const t0 = nowNs();
const { engine, notes } = await loadEngine();
const pushArg = args.find((a) => a.startsWith("--push-digits="));
const results = { quick, date: new Date().toISOString(), machine: machine(), notes };
log(
  `chapgame bench (${quick ? "quick" : "full"}) on ${results.machine.cpu}, ${results.machine.cores} cores, Node ${results.machine.node}`,
);

// The machine's speed before each section and at the end (bench/lib/speedProbe.mjs). A full run
// waits out a slow spell before a section (at most WAIT_MAX_S in all; --no-wait: never).
const probes = [];
const waits = [];
const waitForSteady = !quick && !args.includes("--no-wait");
const sleepS = (s) => new Promise((resolve) => setTimeout(resolve, s * 1000));
const probe = async (at, beforeSection) => {
  const spentS = waits.reduce((sum, w) => sum + w.seconds, 0);
  const earlier = waitForSteady && beforeSection ? probes : [];
  const { probe: p, wait } = await probeWhenSteady(at, earlier, spentS, { sleepS, log });
  if (wait) waits.push(wait);
  probes.push(p);
  log(`   speed probe ${at}: walk ${p.walkNs.toFixed(2)} ns, fp ${p.fpNs.toFixed(2)} ns per step`);
};

const section = async (name, fn) => {
  if (!want(name)) return;
  await probe(`before ${name}`, true);
  log(`== ${name}`);
  const a = nowNs();
  try {
    results[name] = await fn({ quick, engine, log });
  } catch (e) {
    log(`${name}: ERROR ${e.stack ?? e}`);
    results[name] = { error: String(e.message ?? e) };
  }
  log(`   ${name} took ${((nowNs() - a) / 1e9).toFixed(1)} s`);
};

if (pushArg) {
  // Long separate run: Galperin's billiard digit by digit up to N with no time budget, written to
  // bench/results/galperin-push.json; the report merges its rows beyond the main run's.
  const { galperinPush } = await import("./stress/run.mjs");
  const maxDigits = Number(pushArg.slice("--push-digits=".length));
  const push = galperinPush(engine, { maxDigits, budgetSeconds: Number.POSITIVE_INFINITY, log });
  const out = {
    date: new Date().toISOString(),
    machine: machine(),
    seconds: (nowNs() - t0) / 1e9,
    galperinPush: push,
  };
  writeFileSync(join(ROOT, "bench", "results", "galperin-push.json"), `${JSON.stringify(out, null, 1)}\n`);
  log(`wrote bench/results/galperin-push.json; rerun the report with node bench/report/generate.mjs`);
  process.exit(0);
}

await section("solver", runSolver);
await section("peers", runPeers);
await section("engine", runEngine);
await section("stress", runStress);
await probe("at the end", false);
results.speedProbe = summarizeProbes(probes, waits);

results.seconds = (nowNs() - t0) / 1e9;
const file = join(ROOT, "bench", "results", quick ? "tmp/quick.json" : "latest.json");
results.file = relative(ROOT, file);
mkdirSync(dirname(file), { recursive: true });
writeFileSync(file, `${JSON.stringify(results, null, 1)}\n`);
// A quick run never overwrites the committed report: its report goes under the ignored tmp folder.
const reportRoot = quick ? join(ROOT, "bench", "results", "tmp", "quick-report") : ROOT;
const rep = generate(results, { root: reportRoot });
log(
  `wrote ${results.file} and ${rep.files.length} report files under ${relative(ROOT, reportRoot) || "."} in ${results.seconds.toFixed(1)} s`,
);
