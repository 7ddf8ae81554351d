/**
 * Report section 4, numerical stress: the stress cases (overlap, contact error, energy), the far
 * approaches against their closed forms, the long run's energy drift (energy-drift.svg) and Galperin's
 * billiard pushed until it fails (galperinPush.mjs). stressSection(results.stress, out, svgs) appends
 * markdown lines to `out` and SVG texts to `svgs`.
 */
import { dash, int, sig, table } from "./format.mjs";
import { galperinPushBlock } from "./galperinPush.mjs";
import { plot } from "./svg.mjs";

function farSection(F, out) {
  if (!F) return;
  out.push("### Far approaches\n");
  if (F.error) {
    out.push(`error: ${F.error}\n`);
    return;
  }
  out.push(
    "A pair whose path spans a long way before it meets, against its closed form (`bench/stress/far.mjs`): *drop*, a disc of radius 1 at rest at height H falling under gravity onto a point; *slide*, a disc of radius 1 sliding under friction to a resting one L ahead, with the speed to stop 0.5 past the contact. The contact polynomial's terms grow like the span squared, so the engine solves a far approach again near where it happens (`physics/farContact.ts`). Contact error is measured from the reported positions, which cannot be closer than one ulp of the largest coordinate (last column).\n",
  );
  out.push(
    table(
      ["family", "span (radii)", "found", "time error (relative)", "contact error", "one position ulp"],
      F.map((r) => [
        r.family,
        sig(r.span),
        r.found ? "yes" : "**missed**",
        r.found ? sig(r.timeError) : dash,
        r.found ? sig(r.contactError) : dash,
        sig(r.positionUlp),
      ]),
    ),
  );
  out.push("");
}

export function stressSection(s, out, svgs) {
  if (!s) return;
  out.push("## 4. Numerical stress\n");
  if (s.error) {
    out.push(`Not measured: ${s.error}\n`);
    return;
  }
  out.push(
    `Overlap sampled at ${s.samples} instants over each span (all pairs, relative to the contact distance) against the scene's tolerance (1e-9, or a few ulps of a coordinate where coordinates are ~1e6); contact error = |distance − (r1 + r2)| / (r1 + r2) of the two discs at every disc–disc event. The same scenes run as fast invariant tests in \`tests/stress/\`.\n`,
  );
  out.push(
    table(
      [
        "case",
        "bodies",
        "events",
        "time",
        "worst overlap",
        "tolerance",
        "contact error at events",
        "ΔE/E",
        "escaped",
      ],
      s.cases.map((c) =>
        c.error
          ? [c.id, c.bodies, `error: ${c.error}`, "", "", "", "", "", ""]
          : [
              c.id,
              c.bodies,
              int(c.events),
              `${sig(c.ms)} ms`,
              `${sig(c.worstOverlap)}${c.overlapOk ? "" : " ✘"}`,
              sig(c.tolerance),
              sig(c.contactError),
              sig(c.energyError),
              c.escaped,
            ],
      ),
    ),
  );
  out.push("");
  farSection(s.farApproaches, out);
  const L = s.longRun;
  out.push("### Long run: energy drift against event count\n");
  if (L.error) out.push(`error: ${L.error}\n`);
  else {
    out.push(
      `Dilute gas of ${L.bodies} discs, ${int(L.events)} events in ${sig(L.seconds)} s (planned ${int(L.target)} events, or ${L.maxSeconds} s at most${L.events < L.target ? ": **stopped by the time limit**" : ""}); worst |ΔE/E| ${sig(L.worstDrift)}, at the end ${sig(L.finalDrift)}.\n`,
    );
    svgs["energy-drift.svg"] = plot({
      title: "Energy drift over a long run",
      xLabel: "events processed",
      yLabel: "|ΔE/E| (relative kinetic-energy error)",
      xLog: true,
      yLog: true,
      series: [
        {
          name: "chapgame",
          marker: "circle",
          points: L.series.map(([n, e]) => [n, Math.max(1e-17, Math.abs(e))]),
        },
      ],
    });
    out.push("![energy drift](bench/energy-drift.svg)\n");
  }
  galperinPushBlock(s.galperinPush, out);
}
