/**
 * The report's documents, assembled from the sections: buildReport(results) returns
 * { markdown, head, svgs } — docs/benchmarks.md's text (title, machine, speed probes, headline, the
 * four sections, caveats), the headline table alone, and the SVG texts by file name. headlineFile and
 * readmeBlock give the text of docs/benchmarks-headline.md and of the README's headline block.
 * Pure: no file access (generate.mjs writes).
 */

import { engineSection } from "./engine.mjs";
import { sig, table } from "./format.mjs";
import { headline } from "./headline.mjs";
import { peersSection } from "./peers.mjs";
import { solverSection } from "./solver.mjs";
import { speedProbeBlock, speedProbeNote } from "./speedProbe.mjs";
import { stressSection } from "./stress.mjs";

const CAVEATS = [
  "Peers are stepped at a fixed rate; only `step()` is timed (plus, in the friction break, the harness's per-step friction decrement, which a user of those engines must write too). chapgame is timed for one `advance({ untilTime: span })`; scene construction is never timed.",
  "Overlap and escape are sampled at 240 Hz for every engine (every step when the step rate is 240 Hz or lower); the final state is read at the end of the span.",
  "Peer collision counts are the engines' own contact-begin events (matter `collisionStart` pairs, planck `begin-contact`, rapier started collision events). A contact that persists over several steps counts once, so repeated bounces inside one contact are invisible: on Galperin's billiard these counts are a lower bound of what the engine resolved.",
  "Walls: chapgame uses the segments/lines themselves; every peer gets solid boxes behind them (10 units thick for box walls, 0.001 for the thin wall of the tunnelling scene), which helps the peers.",
  "matter-js works in pixels (30 px per unit) and has polygonal circles (25 sides by default, 64 in the tuned run); its resting threshold is a private module-global (`Resolver._restingThresh`) that the harness sets per run and restores.",
  "rapier2d-compat computes in 32-bit floats inside WASM; masses of 1e10 and above (Galperin ≥ 6 digits) are beyond what f32 mass ratios resolve.",
  "The peers have no sliding friction for a top-down table: the break applies μ·g·dt per step to each speed (clamped at zero). Energy is not conserved there by design; the break's error column is the worst overlap.",
  "For the gas scenes there is no exact final state (the dynamics is chaotic); collision counts there are compared with chapgame's count over the same span, which is only a statistical reference.",
];

/**
 * How the side-by-side times were taken: results that record their pass limits (peers.passLimits)
 * were settled first, with those limits; older results were not, and the caveat says what that cost.
 */
/** "1 pass", "20 passes". */
const passes = (n) => `${n} ${n === 1 ? "pass" : "passes"}`;

function timingCaveat(peers) {
  const limits = peers?.passLimits;
  const common =
    "on the machine printed above; ratios measured in the same run are the headline, absolute times are context. A pass longer than 3 s is timed once: the metrics pass itself, which times only `step()` (its JIT warm-up is negligible at that length).";
  if (limits)
    return `Side-by-side timings, chapgame's and every peer's alike: the metrics pass, then warm-up passes of the timed call until the median of the last ${limits.settleWindow} is within ${sig(100 * limits.settleWithin)} % of the fastest (at most ${sig(limits.warmupBudgetNs / 1e9)} s or ${passes(limits.maxWarmup)}; a metrics pass of ${sig(limits.ownWarmupNs / 1e9)} s or more stands for the warm-up), then at least ${passes(limits.minRuns).replace(" ", " timed ")} (up to ${limits.maxRuns} while they total under ${sig(limits.softBudgetNs / 1e9)} s); the time is their median, the brackets give the fastest and the slowest pass. No garbage collection is forced between the passes (it would throw away the compiled code: bench/README.md, "Side-by-side timings"); times ${common}`;
  return `Timings are medians of the runs listed (after a warm-up pass that also collects the metrics, then a forced garbage collection) ${common} These rows were timed before the side-by-side timings were settled (bench/README.md, "Side-by-side timings"): the forced collection threw away the code the warm-up pass had compiled, so the short rows' medians include passes of partly unoptimised code and changed up to 3× between runs of the same code.`;
}

const MACHINE_CAVEATS = [
  "The machine is shared: other processes (builds and test runs in the same checkout) may run during the benchmark, which inflates absolute times unevenly; the solver methods are therefore timed round-robin, and every ratio in the headline is between numbers of the same run.",
];

function machineBlock(r) {
  const m = r.machine;
  return table(
    ["cpu", "cores", "memory", "platform", "node", "v8", "mode", "run took", "date"],
    [
      [
        m.cpu,
        m.cores,
        `${m.memoryGiB} GiB`,
        m.platform,
        m.node,
        m.v8,
        r.quick ? "quick (`--quick`)" : "full",
        `${sig(r.seconds)} s`,
        r.date,
      ],
    ],
  );
}

export function buildReport(results) {
  const svgs = {};
  const out = [];
  out.push("# Benchmarks\n");
  out.push(
    `Generated by \`npm run bench${results.quick ? " -- --quick" : ""}\` from \`${results.file}\`; do not edit by hand: rerun \`npm run bench\` (full, ≈ 10–20 min) or \`npm run bench -- --quick\` (< 2 min). Layout and options: [bench/README.md](../bench/README.md).\n`,
  );
  out.push(machineBlock(results));
  out.push("");
  out.push(...speedProbeBlock(results));
  if (results.notes?.length) out.push(`Notes: ${results.notes.join("; ")}.\n`);
  out.push("## Headline\n");
  const head = headline(results);
  out.push(head);
  out.push("");
  solverSection(results.solver, out, svgs);
  peersSection(results.peers, out, svgs);
  engineSection(results.engine, out, svgs);
  stressSection(results.stress, out, svgs);
  out.push("## Caveats\n");
  const caveats = [...CAVEATS, timingCaveat(results.peers), ...MACHINE_CAVEATS];
  out.push(caveats.map((c) => `- ${c}`).join("\n"));
  out.push("");
  return { markdown: `${out.join("\n")}\n`, head, svgs };
}

/** docs/benchmarks-headline.md: the headline table and one machine line. */
export function headlineFile(results, head) {
  return `<!-- generated by npm run bench from ${results.file}; details in docs/benchmarks.md -->\n${head}\n\nMachine: ${results.machine.cpu}, ${results.machine.cores} cores, Node ${results.machine.node}${results.quick ? " (quick run)" : ""}.${speedProbeNote(results)} Details: [docs/benchmarks.md](docs/benchmarks.md).\n`;
}

/** The README's block between the bench-headline markers (the same headline, with the run's date). */
export function readmeBlock(results, head) {
  return `${head}\n\nMachine: ${results.machine.cpu}, ${results.machine.cores} cores, Node ${results.machine.node}${results.quick ? " (quick run)" : ""}; ${results.date}${runLength(results)}.${speedProbeNote(results)} Details: [docs/benchmarks.md](docs/benchmarks.md).`;
}

/** ", the run took N s" from the run's own clock (runs that did not record it: nothing). */
function runLength(results) {
  return typeof results.seconds === "number" ? `, the run took ${Math.round(results.seconds)} s` : "";
}
