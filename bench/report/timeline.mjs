/**
 * Report section 3, the Timeline subsection: prolong rate, stateAt latency, history bytes, and the
 * cost of an edit at a fraction of the horizon. timelineBlock(engineResults, out) appends markdown
 * lines to `out` ("Not measured" when the run has no timeline data).
 */
import { int, sig, table } from "./format.mjs";

export function timelineBlock(e, out) {
  const t = e.timeline;
  out.push("### Timeline\n");
  if (!t || t.error) out.push(`Not measured: ${t?.error ?? "no data"}\n`);
  else
    out.push(
      `${table(
        [
          "bodies",
          "span",
          "events",
          "prolong events/s",
          "stateAt median",
          "stateAt p95",
          "history bytes",
          "bytes per event",
        ],
        [
          [
            t.bodies,
            t.span,
            int(t.events),
            int(t.prolongEventsPerSecond),
            `${sig(t.stateAtMedianUs)} µs`,
            `${sig(t.stateAtP95Us)} µs`,
            int(t.historyBytes),
            sig(t.bytesPerEvent),
          ],
        ],
      )}\n`,
    );
  if (t && !t.error && t.stateAtMaxUs !== undefined)
    out.push(
      `stateAt worst of the sampled times: ${sig(t.stateAtMaxUs)} µs (target ≤ 1 ms at any t, 1,000 bodies, 10^6 events; bytes per event target < 64).\n`,
    );
  if (t?.edits)
    out.push(
      `${table(
        ["edit at (fraction of horizon)", "recomputed events", "time", "µs per recomputed event"],
        t.edits.map((x) => [
          x.fraction,
          int(x.recomputedEvents),
          `${sig(x.ms)} ms`,
          sig(x.usPerRecomputedEvent),
        ]),
      )}\n`,
    );
}
