/**
 * Report section 3, mixed radii (bench/engine/mixedRadii.mjs): events/s of the 10 % gas around one
 * disc of radius 1 to 100, beside the gas without a big disc. mixedRadiiBlock(engineResults, out)
 * appends markdown lines to `out`; a run from before this row existed gets nothing.
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
    `A 10 % gas of ${int(m.rows[0]?.n)} discs of radius 1 (speed 10) around one disc of mass r² at rest at the centre of the box (\`bench/scenes/bigDisc.mjs\`); radius 1 is the gas without a big disc. The grid's cells are sized for the small discs and the big disc is tested against every body instead (at most eight such discs: \`GRID_BIG_BODIES_MAX\`), so it costs its own events O(N) and the other events nothing. Rows run one after the other in one process, each on a fresh World after a warm-up, then timed batches (median).\n`,
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
}
