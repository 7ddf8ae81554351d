/**
 * Report section 1, the root solver: time per call against error on random collision quartics
 * (table, target line, solver.svg) and the hard-case table. solverSection(results.solver, out, svgs)
 * appends markdown lines to `out` and SVG texts to `svgs` (file name → text); nothing without data.
 */
import { dash, int, sig, status, table } from "./format.mjs";
import { plot } from "./svg.mjs";

export function solverSection(s, out, svgs) {
  if (!s) return;
  out.push("## 1. Root solver: time per call against error\n");
  if (s.error) {
    out.push(`Not measured: ${s.error}\n`);
    return;
  }
  const rnd = s.random;
  out.push(
    `${int(rnd.count)} random collision quartics |d + u t + w t²/2|² − R² (seeded LCG ${rnd.seed}, interval [${rnd.interval.join(", ")}]). ` +
      "Error = ulps from the computed root to the nearest point where the exact polynomial (the double coefficients taken exactly, BigInt arithmetic via the engine's `exactPolySign`) is zero or changes sign, found by a doubling search then bisection on the ulp index. " +
      '"missed" = roots that the best method found near a true sign change but this one did not return; "spurious" = returned roots with no sign change within 2^62 ulps. ' +
      `Times: the median over ${rnd.methods[0]?.processes ?? 1} fresh process(es) that load only the solver benchmark (per process: ${rnd.methods.map((m) => `${m.id} ${(m.nsPerCallPerProcess ?? []).map((x) => sig(x)).join(", ")}`).join("; ")} ns), each the median of interleaved passes; in a process that has loaded every section's modules the same code measured up to 25 % slower (bench/solver/timing.mjs).\n`,
  );
  const rr = rnd.methods.find((m) => m.id === "realRoots");
  const bis = rnd.methods.find((m) => m.id === "bisection");
  out.push(
    table(
      [
        "method",
        "ns per call (random)",
        "ns per call (hard set)",
        "median ulps",
        "p99 ulps",
        "worst ulps",
        "missed",
        "spurious",
      ],
      rnd.methods.map((m) => [
        m.label,
        sig(m.nsPerCall),
        sig(s.hardTiming.find((h) => h.id === m.id)?.nsPerCall),
        sig(m.medianUlps),
        sig(m.p99Ulps),
        sig(m.worstUlps),
        m.missed,
        m.spurious,
      ]),
    ),
  );
  out.push("");
  if (rr && bis)
    out.push(
      `Target: realRoots ≤ ${s.targetNs} ns per call (median) — measured ${sig(rr.nsPerCall)} ns: ${status(rr.nsPerCall <= s.targetNs)}. ` +
        `Same run: ${sig(bis.nsPerCall / rr.nsPerCall)}× the speed of the seed's bisection, with median error ${sig(rr.medianUlps)} ulps against ${sig(bis.medianUlps)}.\n`,
    );
  svgs["solver.svg"] = plot({
    title: "Root solvers: time per call vs error",
    xLabel: "median ns per call (random collision quartics)",
    yLabel: "error in ulps + 1",
    xLog: true,
    yLog: true,
    series: [
      ...(() => {
        const all = rnd.methods.flatMap((m) => [m.medianUlps, m.worstUlps]).filter(Number.isFinite);
        return [
          {
            name: `target ${s.targetNs} ns`,
            marker: "none",
            color: "#888",
            points: [
              [s.targetNs, 1],
              [s.targetNs, Math.max(10, ...all) + 1],
            ],
          },
        ];
      })(),
      ...rnd.methods.flatMap((m, i) => [
        {
          name: `${m.id} median`,
          marker: "circle",
          line: false,
          color: ["#000", "#d62728", "#1f77b4", "#2ca02c"][i],
          points: [[m.nsPerCall, (m.medianUlps ?? Number.NaN) + 1]],
        },
        {
          name: `${m.id} worst`,
          marker: "square",
          line: false,
          color: ["#000", "#d62728", "#1f77b4", "#2ca02c"][i],
          points: [[m.nsPerCall, (m.worstUlps ?? Number.NaN) + 1]],
        },
      ]),
    ],
  });
  out.push("![solver: time vs error](bench/solver.svg)\n");
  out.push(
    "Hard cases (kinds used in published quartic test sets: extreme spread, clusters, double and near-double roots, grazing, a near-tangent minimum without real roots). Each cell: roots returned / roots expected, worst error in ulps (exact double roots are measured against the known root).\n",
  );
  const ids = s.hard[0]?.results.map((r) => r.id) ?? [];
  out.push(
    table(
      ["case", "polynomial", ...ids],
      s.hard.map((h) => [
        h.id,
        h.note,
        ...h.results.map(
          (r) => `${r.found}/${h.expected}, ${r.worstUlps === null ? dash : `${sig(r.worstUlps)} ulps`}`,
        ),
      ]),
    ),
  );
  out.push("");
}
