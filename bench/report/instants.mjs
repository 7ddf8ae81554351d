/**
 * Report section 3, one action per call at successive instants (bench/engine/instants.mjs): the time
 * to build a scene of N discs with Timeline.apply, one disc per call at t = 0, 0.01, 0.02, ..., per
 * scene (at rest, or thrown under friction) and with or without history, and how the time per apply
 * grows from the smallest N to the largest (1: linear).
 * instantsBlock(engineResults, out) appends markdown lines to `out`; a run from before these rows
 * existed gets nothing.
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
}
