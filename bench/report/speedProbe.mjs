/**
 * The report's paragraph on the machine's speed during the run (bench/lib/speedProbe.mjs): each
 * probe, the spread, and a plain warning when the speed changed by more than the threshold. Runs
 * from before the probe existed have no `speedProbe`, and get no paragraph.
 */
import { table } from "./format.mjs";

const pct = (x) => `${(100 * x).toFixed(0)} %`;

/** Markdown lines for docs/benchmarks.md, or [] without probes. */
export function speedProbeBlock(results) {
  const sp = results.speedProbe;
  if (!sp?.probes?.length) return [];
  const out = [];
  out.push("### Machine speed during the run\n");
  out.push(
    `A fixed workload timed in a fresh process before each section and at the end (${sp.workload}). The machine is a shared VM whose speed drifts; the guest sees no steal time, so this is how a run shows it.\n`,
  );
  out.push(
    table(
      ["when", "walk, ns per step", "fp, ns per step"],
      sp.probes.map((p) => [p.at, p.walkNs.toFixed(2), p.fpNs.toFixed(2)]),
    ),
  );
  out.push("");
  const waited = waitsSentence(sp);
  if (waited) out.push(`${waited}\n`);
  out.push(
    sp.steady
      ? `Spread (slowest / fastest − 1): walk ${pct(sp.walk.spread)}, fp ${pct(sp.fp.spread)}: within the ${pct(sp.warnAbove)} allowed for this machine's second-to-second jitter, so no slow spell beyond it showed between sections.\n`
      : `**Spread (slowest / fastest − 1): walk ${pct(sp.walk.spread)}, fp ${pct(sp.fp.spread)}, over ${pct(sp.warnAbove)}: the machine's speed changed during this run, so its absolute times are suspect.** Ratios measured side by side within a section (solver methods round-robin, ablation pairs) are less affected.\n`,
  );
  return out;
}

/**
 * What the run did about slow spells before its sections ("" when it never waited; runs from before
 * the waiting existed have no `waits`).
 */
function waitsSentence(sp) {
  const waits = sp.waits ?? [];
  if (waits.length === 0) return "";
  const each = waits.map((w) => {
    const slow = w.slowProbes
      .map((p) => `walk ${p.walkNs.toFixed(2)} / fp ${p.fpNs.toFixed(2)} ns`)
      .join(", ");
    return `${w.before}: probed at ${slow}, waited ${w.seconds} s${w.gaveUp ? ", still slow when the wait limit was reached, measured anyway" : ", then measured at the speed listed above"}`;
  });
  return `A probe more than ${pct(sp.slowBy)} slower than the fastest earlier in the run makes a full run wait before the section and probe again. This run waited ${waits.reduce((s, w) => s + w.seconds, 0)} s: ${each.join("; ")}.`;
}

/** One sentence for the headline's machine line ("" without probes). */
export function speedProbeNote(results) {
  const sp = results.speedProbe;
  if (!sp?.probes?.length) return "";
  return sp.steady
    ? ` Machine speed probes spread ${pct(sp.spread)} during the run (warning above ${pct(sp.warnAbove)}).`
    : ` **Machine speed changed by ${pct(sp.spread)} during the run: absolute times are suspect.**`;
}
