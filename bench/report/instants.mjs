/**
 * Report section 3, one action per call at successive instants (bench/engine/instants.mjs): the time
 * to build a scene of N discs with Timeline.apply, one disc per call at t = 0, 0.01, 0.02, ..., per
 * scene (at rest, or thrown under friction) and with or without history, and how the time per apply
 * grows from the smallest N to the largest (1: linear).
 * Then the reads over such a history (thrown discs, with history): stateAt, bodyArraysAt and path()
 * per N, with the history's bytes.
 * instantsBlock(engineResults, out) appends markdown lines to `out`; a run from before these rows
 * existed gets nothing (and one from before the reads, no reads table).
 */
import { int, ms, sig, table } from "./format.mjs";

const SCENES = {
  resting: "discs at rest on a lattice",
  thrown: "discs thrown under friction",
};

export function instantsBlock(e, out) {
  const b = e.instants;
  if (!b) return;
  out.push("### A scene built one action per call at successive instants\n");
  if (b.error) {
    out.push(`Not measured: ${b.error}\n`);
    return;
  }
  const sizes = b.rows[0]?.points.map((p) => p.n) ?? [];
  out.push(
    `N discs applied with \`Timeline.apply\`, one per call at t = 0, ${b.dt}, ${2 * b.dt}, … (an editor adding discs at different times, a game spawning a body every frame); each time is the median of ${b.runs} fresh builds. The last column is the time per apply at N = ${int(sizes[sizes.length - 1])} over that at N = ${int(sizes[0])}: 1 is linear.\n`,
  );
  out.push(
    table(
      ["scene", "history", ...sizes.map((n) => `N = ${int(n)}`), "per apply, largest / smallest N"],
      b.rows.map((r) => [
        SCENES[r.scene] ?? r.scene,
        r.history ? "yes" : "no",
        ...r.points.map((p) => ms(p.ms * 1e6)),
        `${sig(r.scaling)}×`,
      ]),
    ),
  );
  out.push("");
  const reads = b.reads;
  if (!reads?.rows?.length) return;
  const ways = reads.rows[0].ways;
  out.push(
    `Reads over such a history (discs thrown under friction, with history: a keyframe per instant, most of them deltas of the one before): \`stateAt\` and \`bodyArraysAt(t, into)\` at ${reads.count} times spread over it, backwards (each read loads its keyframe) and forwards (playback), and \`path(id)\` of three discs over the whole history; time per call, the median of ${reads.passes} passes.\n`,
  );
  out.push(
    table(
      ["N", "events", "history", ...ways.map((w) => `${w.name}, ${w.order}`)],
      reads.rows.map((r) => [
        int(r.n),
        int(r.events),
        `${sig(r.historyBytes / 1e6)} MB`,
        ...r.ways.map((w) => ms(w.ms * 1e6)),
      ]),
    ),
  );
  out.push("");
}
