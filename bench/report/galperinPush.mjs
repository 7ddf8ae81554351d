/**
 * Report section 4, Galperin's billiard pushed until it fails: mergePush folds the rows of a separate
 * `--push-digits` run into the main run's results (mutating them, as the report did before), and
 * galperinPushBlock(stress.galperinPush, out) appends the table and the measured explanation of where
 * and why the count goes wrong (or, when no digit count failed, where it is expected to).
 */
import { existsSync, readFileSync } from "node:fs";
import { int, sig, table } from "./format.mjs";

/**
 * Merge the rows of a separate `--push-digits` run (the JSON at `file`, normally
 * bench/results/galperin-push.json) that go beyond what the main run measured; those rows say where
 * they come from.
 */
export function mergePush(results, file) {
  const P = results.stress?.galperinPush;
  if (!P || !existsSync(file)) return;
  const extra = JSON.parse(readFileSync(file, "utf8"));
  const measured = new Set(P.rows.filter((r) => !r.skipped).map((r) => r.digits));
  const add = extra.galperinPush.rows
    .filter((r) => !r.skipped && !measured.has(r.digits))
    .map((r) => ({ ...r, source: `separate run \`--push-digits\` of ${extra.date.slice(0, 10)}` }));
  if (add.length === 0) return;
  P.rows = [...P.rows.filter((r) => !r.skipped), ...add].sort((a, b) => a.digits - b.digits);
  P.firstWrong = P.rows.find((r) => r.correct === false)?.digits ?? null;
  P.lastCorrect = P.rows.filter((r) => r.correct).at(-1)?.digits ?? 0;
}

export function galperinPushBlock(P, out) {
  out.push("### Galperin's billiard pushed until it fails\n");
  out.push(
    table(
      [
        "digits",
        "exact",
        "counted",
        "correct",
        "time",
        "smallest gap between event times (at t)",
        "events at an identical time",
        "last event at",
        "error / note",
      ],
      P.rows.map((r) =>
        r.skipped
          ? [r.digits, "", "", "not run", "", "", "", "", r.skipped]
          : [
              r.digits,
              int(r.expected),
              int(r.count),
              r.correct ? "yes" : "**no**",
              `${sig(r.seconds)} s`,
              `${sig(r.minGap)}${r.minGapAt ? ` (${sig(r.minGapAt)})` : ""}`,
              int(r.sameTime),
              sig(r.lastTime, 17),
              [r.error, r.source].filter(Boolean).join("; "),
            ],
      ),
    ),
  );
  out.push("");
  out.push(galperinExplanation(P));
}

/** The why, in terms of the measured numbers of the failing (or last) row. */
function galperinExplanation(P) {
  const bad = P.rows.find((r) => r.correct === false);
  const last = P.rows.filter((r) => r.correct).at(-1);
  const lines = [];
  if (!bad) {
    lines.push(
      `Every digit count run was correct (up to ${last?.digits ?? 0} digits); the next one was not run (each digit costs 10× the events of the one before), so the first wrong digit count is not measured.`,
    );
    const ulpAt = (t) => 2 ** (Math.floor(Math.log2(t)) - 52);
    const resolved = P.rows.filter(
      (r) => r.correct && Number.isFinite(r.minGap) && r.minGap > 4 * ulpAt(r.minGapAt || r.lastTime),
    );
    const trend = resolved.at(-1);
    if (trend && last) {
      const at = trend.minGapAt || trend.lastTime;
      const gapAt = (d) => trend.minGap / 100 ** (d - trend.digits);
      const next = last.digits + 1;
      const parts = [
        `Why it should break, and where (an extrapolation, labelled as such): the smallest gap between event times shrinks 100× per digit (${sig(trend.minGap)} at ${trend.digits} digits, near t = ${sig(at)}, where one ulp of t is ${sig(ulpAt(at))}).`,
      ];
      const saturated = P.rows.filter((r) => r.correct && r.digits > trend.digits);
      for (const r of saturated)
        parts.push(
          `At ${r.digits} digits the unrounded gap would be ≈ ${sig(gapAt(r.digits))}, and the measured smallest gap is ${sig(r.minGap)}, i.e. ${sig(r.minGap / ulpAt(r.minGapAt || r.lastTime))} ulp: collision times are already rounded to neighbouring doubles, yet the count is right, because wall and disc collisions strictly alternate in this billiard (after a disc–disc collision the light disc can only reach the wall), so rounding cannot reorder events; the count is decided by the velocities, which each collision updates to round-off.`,
        );
      parts.push(
        `At ${next} digits the gaps would be ≈ ${sig(gapAt(next))}, ${sig(ulpAt(at) / gapAt(next))}× below one ulp: many collisions would have to share one double time and positions move by less than their own ulp between them, so the count is expected to go wrong there. Not measured: ${int(10 * last.expected)} events, about ${sig((10 * last.seconds) / 3600)} h at the measured rate.`,
      );
      lines.push(parts.join(" "));
    }
  } else {
    const M = 100 ** (bad.digits - 1);
    const at = bad.minGapAt || bad.lastTime;
    const ulpT = 2 ** (Math.floor(Math.log2(Math.max(at, 1e-300))) - 52);
    lines.push(
      `First wrong digit count: **${bad.digits}** (counted ${int(bad.count)}, exact ${int(bad.expected)}${bad.error ? `; the run stopped with: ${bad.error}` : ""}).`,
    );
    lines.push(
      `Why: with mass ratio M = 100^${bad.digits - 1} = ${sig(M)} the light disc reaches speed ≈ √M = ${sig(Math.sqrt(M))} and, near the heavy disc's turning point, gaps of ≈ ${sig(1 / Math.sqrt(M))}, so consecutive collisions are ≈ 1/M = ${sig(1 / M)} apart in time. ` +
        `Event times are doubles near t ≈ ${sig(at)} (where the collisions crowd), where one ulp is ${sig(ulpT)}; the smallest gap measured between distinct event times was ${sig(bad.minGap)} and ${int(bad.sameTime)} events fell on an identical time. ` +
        `Once 1/M approaches the ulp of t, collision times can no longer be told apart (and the velocity update's (M − m)/(M + m) loses the light disc's contribution: M + 1 = M in doubles once M > 2^53 ≈ 9.0e15), so the count drifts off π's digits. This is a limit of double precision, not of the method; exact (rational) time and velocity arithmetic would push it further.`,
    );
  }
  return `${lines.join("\n\n")}\n`;
}
