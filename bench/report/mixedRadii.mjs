/**
 * Report section 3, mixed radii (bench/engine/mixedRadii.mjs): events/s of the 10 % gas around one
 * disc of radius 1 to 100, beside the gas without a big disc, then of gases with many large discs
 * or radii spread over a range. mixedRadiiBlock(engineResults, out) appends markdown lines to
 * `out`; a run from before these rows existed gets nothing (or only the first table).
 */
import { int, pct, sig, table } from "./format.mjs";

export function mixedRadiiBlock(e, out) {
  const m = e.mixedRadii;
  if (!m) return;
  out.push("### Mixed radii: one big disc among small ones\n");
  if (m.error) {
    out.push(`Not measured: ${m.error}\n`);
    return;
  }
  const base = m.rows.find((r) => r.bigR === 1 && !r.error);
  out.push(
    `A 10 % gas of ${int(m.rows[0]?.n)} discs of radius 1 (speed 10) around one disc of mass r² at rest at the centre of the box (\`bench/scenes/bigDisc.mjs\`); radius 1 is the gas without a big disc. The grid's level-0 cells are sized for the small discs and the big disc sits in a coarser level of cells (\`sim/grid.ts\`), so it costs its own events a scan of the small discs' cells near it and the other events almost nothing. Rows run one after the other in one process, each on a fresh World after a warm-up, then timed batches (median).\n`,
  );
  out.push(
    table(
      [
        "big disc radius",
        "events per batch",
        "runs",
        "events/s",
        "events with the big disc",
        "events/s vs no big disc",
      ],
      m.rows.map((r) =>
        r.error
          ? [r.bigR, "", "", `error: ${r.error}`, "", ""]
          : [
              r.bigR,
              int(r.batch),
              r.runs,
              int(r.eventsPerSecond),
              pct(r.bigEventShare),
              base ? `${sig(r.eventsPerSecond / base.eventsPerSecond)}×` : "—",
            ],
      ),
    ),
  );
  out.push("");
  manyBlock(m, base, out);
}

function manyBlock(m, base, out) {
  if (!m.manyRows) return;
  out.push("### Mixed radii: many large discs, and radii over a range\n");
  out.push(
    `10 % gases of ${int(m.manyRows[0]?.n)} discs, m = r², speed 10, placed at seeded random spots (\`bench/scenes/polydisperse.mjs\`). The grid uses levels only where \`sim/gridCost.ts\` estimates they cut the cost per prediction (pair tests and cell visits) to 65 % or less of one level's (\`GRID_LEVEL_GAIN\`); radii spread evenly on a log scale stay in one level of cells sized for the largest disc. Same timing as above; the last column compares with the gas of radius 1 alone (first table).\n`,
  );
  out.push(
    table(
      ["radii", "events per batch", "runs", "events/s", "events/s vs radius 1 alone"],
      m.manyRows.map((r) =>
        r.error
          ? [r.law, "", "", `error: ${r.error}`, ""]
          : [
              r.law,
              int(r.batch),
              r.runs,
              int(r.eventsPerSecond),
              base ? `${sig(r.eventsPerSecond / base.eventsPerSecond)}×` : "—",
            ],
      ),
    ),
  );
  out.push("");
}
