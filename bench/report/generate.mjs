/**
 * Report generator: results JSON → docs/benchmarks.md, docs/bench/*.svg and
 * docs/benchmarks-headline.md. Nothing in the report is typed by hand: every number comes from the
 * JSON; the prose here only names what was measured and the fixed caveats of the method.
 * Usage: node bench/report/generate.mjs [results.json]   (default bench/results/latest.json)
 */
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { dash, int, ms, sig, status, table } from "./format.mjs";
import { galperinTable, scenePlot, sceneTable, settingsSection } from "./peers.mjs";
import { speedProbeBlock, speedProbeNote } from "./speedProbe.mjs";
import { plot } from "./svg.mjs";

const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..", "..");

/** What each World `optimizations` switch skips (from the engine's Optimizations contract). */
const SKIPS = {
  broadPhase: "cell grid with crossing events (off: every body against every body)",
  quadraticFastPath: "closed-form quadratic when the relative acceleration is zero (off: the quartic solver)",
  pathBounds:
    "pairs whose remaining paths (friction: finite segments) cannot meet are rejected before solving",
  restingSkip: "pairs of resting bodies are never tested",
};

/** Why a switch can show no gain on a given scene (printed only when a run measures none). */
const WEAK_WHY = {
  restingSkip:
    "with it off a resting pair still never reaches a polynomial: zero relative velocity and acceleration, so the receding test rejects it first; it saves loads and a call per pair, which shows where many resting discs are re-predicted",
  pathBounds:
    "it rejects pairs whose friction paths cannot meet, but the grid already limits tests to neighbouring cells; it pays where paths are short beside the cell size",
};

const CAVEATS = [
  "Peers are stepped at a fixed rate; only `step()` is timed (plus, in the friction break, the harness's per-step friction decrement, which a user of those engines must write too). chapgame is timed for one `advance({ untilTime: span })`; scene construction is never timed.",
  "Overlap and escape are sampled at 240 Hz for every engine (every step when the step rate is 240 Hz or lower); the final state is read at the end of the span.",
  "Peer collision counts are the engines' own contact-begin events (matter `collisionStart` pairs, planck `begin-contact`, rapier started collision events). A contact that persists over several steps counts once, so repeated bounces inside one contact are invisible: on Galperin's billiard these counts are a lower bound of what the engine resolved.",
  "Walls: chapgame uses the segments/lines themselves; every peer gets solid boxes behind them (10 units thick for box walls, 0.001 for the thin wall of the tunnelling scene), which helps the peers.",
  "matter-js works in pixels (30 px per unit) and has polygonal circles (25 sides by default, 64 in the tuned run); its resting threshold is a private module-global (`Resolver._restingThresh`) that the harness sets per run and restores.",
  "rapier2d-compat computes in 32-bit floats inside WASM; masses of 1e10 and above (Galperin ≥ 6 digits) are beyond what f32 mass ratios resolve.",
  "The peers have no sliding friction for a top-down table: the break applies μ·g·dt per step to each speed (clamped at zero). Energy is not conserved there by design; the break's error column is the worst overlap.",
  "For the gas scenes there is no exact final state (the dynamics is chaotic); collision counts there are compared with chapgame's count over the same span, which is only a statistical reference.",
  "Timings are medians of the runs listed (after a warm-up pass that also collects the metrics), on the machine printed above; ratios measured in the same run are the headline, absolute times are context. A peer pass longer than 3 s is timed once: the metrics pass itself, which times only `step()` (its JIT warm-up is negligible at that length).",
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

/**
 * What the stripped loops say about each gas target, in this run: a target that every loop misses
 * is out of reach of tuning the engine (it needs another algorithm); one that a loop meets could be
 * met by an implementation like that loop.
 */
function ceilingVerdict(sc) {
  const t = sc.targets;
  const said = [];
  const judge = (what, js, wasm, ok) => {
    const met = [
      js !== null && ok(js) ? "JavaScript" : null,
      wasm !== null && wasm !== undefined && ok(wasm) ? "WebAssembly" : null,
    ].filter(Boolean);
    said.push(
      met.length === 0
        ? `The ${what} target is missed even by these loops: it is out of reach of tuning the engine on this machine and needs a different algorithm, not a faster implementation of this one.`
        : `The ${what} target is met in this run by the stripped ${met.join(" and ")} loop: an implementation like ${met.length > 1 ? "them" : "it"} could meet it.`,
    );
  };
  judge(
    "events/s",
    sc.minimalEventsPerSecondAt1e4,
    sc.wasmEventsPerSecondAt1e4,
    (v) => v >= t.eventsPerSecondAt1e4,
  );
  judge("cost-ratio", sc.minimalCostRatio1e5over1e3, sc.wasmCostRatio1e5over1e3, (v) => v <= t.costRatio);
  return said.join(" ");
}

function solverSection(s, out, svgs) {
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

function peersSection(p, out, svgs) {
  if (!p) return;
  out.push("## 2. chapgame against the peers\n");
  out.push(
    `Fixed steps: ${p.rates.join(", ")} Hz. Configurations: **tuned** = restitution 1, friction 0, thresholds off, CCD/bullets on where they exist; **defaults** = the same scene physics (restitution 1, friction 0, no damping, no sleeping, rotations locked) with every engine knob at its default.\n`,
  );
  out.push("### Peer settings\n");
  out.push(settingsSection(p.settings));
  out.push("### Galperin's billiard: collisions counted\n");
  out.push(galperinTable(p.scenes, p.rates));
  out.push("");
  const names = Object.keys(p.settings);
  for (const scene of p.scenes) {
    out.push(`### ${scene.title}\n`);
    out.push(
      `${scene.description}${scene.peersSkipped ? ` Peers: ${scene.peersSkipped} (they already fail at 3 digits).` : ""}\n`,
    );
    const file = `peers-${scene.id}.svg`;
    svgs[file] = scenePlot(scene, names);
    out.push(`![${scene.id}](bench/${file})\n`);
    out.push(sceneTable(scene));
    out.push("");
  }
}

function engineSection(e, out, svgs) {
  if (!e) return;
  out.push("## 3. Engine scaling, Galperin 7 digits, optimisations\n");
  if (e.error) {
    out.push(`Not measured: ${e.error}\n`);
    return;
  }
  const sc = e.scaling;
  out.push(
    "Dilute gas (10 % packing, r = 1, speed 10, box walls), timed batches of events after a warm-up that leaves the grid start; events/s = batch / median batch time. Each N runs in fresh Node processes (no JIT state from other rows or sections; the engine and both loops compiled first on a small gas), three per N in full runs, in rounds of one process per N (so a drift of the machine's speed falls on every N alike, not on N = 10⁵, measured last), with the median kept, because at 10⁵ discs one process's rate differs from the next by up to 30 % (memory placement) while its own batches agree; the per-process rates are in latest.json. Memory per body = growth of the JS heap plus ArrayBuffer memory (where typed arrays live) when building and preparing (grid and event queue) copies of the world holding at least 10⁵ bodies in all, / bodies; typed arrays grow by doubling, so it varies with how full they are.\n",
  );
  out.push(
    table(
      [
        "N",
        "events per batch",
        "runs",
        "events/s",
        "ns per event",
        "minimal loop, JS, events/s",
        "minimal loop, WebAssembly, events/s",
        "memory per body, bytes",
        "build time",
      ],
      sc.rows.map((r) =>
        r.error
          ? [int(r.n), `error: ${r.error}`, "", "", "", "", "", "", ""]
          : [
              int(r.n),
              int(r.batch),
              r.runs,
              int(r.eventsPerSecond),
              sig(r.nsPerEvent),
              r.minimalEventsPerSecond === undefined ? "—" : int(r.minimalEventsPerSecond),
              r.wasmError
                ? `error: ${r.wasmError}`
                : r.wasmEventsPerSecond == null
                  ? "—"
                  : int(r.wasmEventsPerSecond),
              int(r.heapBytesPerBody),
              ms(r.buildNs),
            ],
      ),
    ),
  );
  out.push("");
  out.push(
    `- Events/s at N = 10,000: ${int(sc.eventsPerSecondAt1e4)} (target ≥ ${int(sc.targets.eventsPerSecondAt1e4)}): ${status(sc.eventsPerSecondAt1e4 === null ? null : sc.eventsPerSecondAt1e4 >= sc.targets.eventsPerSecondAt1e4)}.`,
  );
  out.push(
    `- Cost per event at N = 100,000 / N = 1,000: ${sig(sc.costRatio1e5over1e3)} (target ≤ ${sc.targets.costRatio}): ${status(sc.costRatio1e5over1e3 === null ? null : sc.costRatio1e5over1e3 <= sc.targets.costRatio)}.`,
  );
  if (sc.minimalEventsPerSecondAt1e4 != null) {
    const wasm =
      sc.wasmEventsPerSecondAt1e4 == null
        ? ""
        : ` Its WebAssembly twin (\`bench/wasm\`: AssemblyScript -O3, unchecked array access, the same event sequence bit for bit) reaches ${int(sc.wasmEventsPerSecondAt1e4)} events/s and a ratio of ${sig(sc.wasmCostRatio1e5over1e3)}.`;
    out.push(
      `- Ceilings: the same algorithm with every product feature stripped (\`bench/engine/minimalGas.mjs\`: no API, ids, tie order, friction, gravity, lines or reports) reaches ${int(sc.minimalEventsPerSecondAt1e4)} events/s at N = 10,000 in JavaScript and a cost ratio of ${sig(sc.minimalCostRatio1e5over1e3)} between N = 100,000 and 1,000.${wasm} ${ceilingVerdict(sc)}`,
    );
  }
  const g = e.galperin7;
  if (g.error) out.push(`- Galperin's billiard, 7 digits: error: ${g.error}.`);
  else
    out.push(
      `- Galperin's billiard, 7 digits: ${int(g.count)} collisions (exact ${int(g.expected)}${g.correct ? ", correct" : ", WRONG"}) in ${sig(g.seconds)} s (target < 2 s): ${status(g.correct && g.seconds < 2)}.`,
    );
  out.push("");
  const ok = sc.rows.filter((r) => !r.error);
  svgs["scaling.svg"] = plot({
    title: "Dilute gas: events per second against N",
    xLabel: "N (discs)",
    yLabel: "events per second",
    xLog: true,
    yLog: true,
    series: [
      { name: "chapgame", points: ok.map((r) => [r.n, r.eventsPerSecond]) },
      {
        name: "target at 1e4",
        marker: "diamond",
        line: false,
        points: [[1e4, sc.targets.eventsPerSecondAt1e4]],
      },
    ],
  });
  out.push("![scaling](bench/scaling.svg)\n");
  out.push(
    'Each "skip what the scene does not need" optimisation switched off in turn (World option `optimizations: { <flag>: false }`), same scene and span; "same events" checks that the switch changes only the time. Each configuration runs in its own Node process (warmed up, then timed), as a program using one configuration would: in a shared process the JIT\'s type feedback from one skews the other. On and off alternate over three process pairs (one in a quick run) and the times are the medians over all their timed runs, so a drift of the machine\'s speed during the section falls on both.\n',
  );
  out.push(
    table(
      ["optimisation off", "scene", "bodies", "events", "same events", "time on", "time off", "off / on"],
      e.ablations.map((a) =>
        a.error
          ? [a.flag, a.scene, "", `error: ${a.error}`, "", "", "", ""]
          : [
              `${a.flag}: ${SKIPS[a.flag] ?? ""}`,
              a.description,
              a.bodies,
              int(a.events),
              a.sameEvents ? "yes" : `no (${int(a.eventsOff)})`,
              `${sig(a.msOn)} ms`,
              `${sig(a.msOff)} ms`,
              `${sig(a.speedup)}×`,
            ],
      ),
    ),
  );
  out.push("");
  const weak = e.ablations.filter((a) => !a.error && a.speedup < 1.1).map((a) => a.flag);
  if (weak.length > 0)
    out.push(
      `Switches without a clear gain (under 1.1×) in this run: ${weak.map((f) => `\`${f}\`${WEAK_WHY[f] ? ` (${WEAK_WHY[f]})` : ""}`).join("; ")}. They stay: each costs a load or two per pair, and \`optimizations\` is public API.\n`,
    );
  const ref = e.reference;
  out.push("### Against the all-pairs reference simulator\n");
  out.push(
    "The engine tests' deliberately simple reference (`packages/engine/test/referenceWorld.ts`: every pair recomputed after every event, the seed's method), transpiled by the benchmark from its TypeScript source; same dilute gas, same number of events, and the two event sequences compared (kind, participants, time to 1e-12 relative).\n",
  );
  if (!ref || ref.error) out.push(`Not measured: ${ref?.error ?? "no data"}\n`);
  else
    out.push(
      `${table(
        [
          "N",
          "events",
          "reference events/s",
          "chapgame events/s",
          "chapgame / reference",
          "same event sequence",
        ],
        ref.rows.map((r) =>
          r.error
            ? [int(r.n), int(r.events), `error: ${r.error}`, "", "", ""]
            : [
                int(r.n),
                int(r.events),
                int(r.refEventsPerSecond),
                int(r.fastEventsPerSecond),
                `${sig(r.speedup)}×`,
                r.sameSequence ? "yes" : `no (first difference at event ${r.firstDiff})`,
              ],
        ),
      )}\n`,
    );
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

function stressSection(s, out, svgs) {
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
  const P = s.galperinPush;
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

function headline(r) {
  const rows = [];
  const s = r.solver;
  const rr = s?.random?.methods.find((m) => m.id === "realRoots");
  const bis = s?.random?.methods.find((m) => m.id === "bisection");
  if (rr && bis)
    rows.push([
      "root solver, ns per call (collision quartics)",
      `${sig(rr.nsPerCall)} ns, median ${sig(rr.medianUlps)} ulps`,
      `seed bisection: ${sig(bis.nsPerCall)} ns, median ${sig(bis.medianUlps)} ulps`,
      `≤ ${s.targetNs} ns`,
      status(rr.nsPerCall <= s.targetNs),
    ]);
  const e = r.engine;
  if (e && !e.error) {
    const sc = e.scaling;
    rows.push([
      "dilute gas, events/s at N = 10,000",
      int(sc.eventsPerSecondAt1e4),
      sc.minimalEventsPerSecondAt1e4 == null
        ? dash
        : `stripped loop: JS ${int(sc.minimalEventsPerSecondAt1e4)}${sc.wasmEventsPerSecondAt1e4 == null ? "" : `, WebAssembly ${int(sc.wasmEventsPerSecondAt1e4)}`}`,
      "≥ 1,000,000",
      status(sc.eventsPerSecondAt1e4 === null ? null : sc.eventsPerSecondAt1e4 >= 1e6),
    ]);
    rows.push([
      "cost per event, N = 100,000 vs 1,000",
      `${sig(sc.costRatio1e5over1e3)}×`,
      sc.minimalCostRatio1e5over1e3 == null
        ? dash
        : `stripped loop: JS ${sig(sc.minimalCostRatio1e5over1e3)}×${sc.wasmCostRatio1e5over1e3 == null ? "" : `, WebAssembly ${sig(sc.wasmCostRatio1e5over1e3)}×`}`,
      "≤ 2×",
      status(sc.costRatio1e5over1e3 === null ? null : sc.costRatio1e5over1e3 <= 2),
    ]);
    const g = e.galperin7;
    rows.push([
      "Galperin 7 digits (3,141,592 collisions)",
      g.error ? `error` : `${int(g.count)} in ${sig(g.seconds)} s`,
      dash,
      "< 2 s, exact count",
      status(g.error ? false : g.correct && g.seconds < 2),
    ]);
  }
  const p = r.peers;
  if (p) {
    const find = (id) => p.scenes.find((x) => x.id === id);
    const gas = find("dilute-gas");
    if (gas?.chapgame && !gas.chapgame.error) {
      const best = gas.peers
        .filter((q) => !q.error && q.hz === 60 && q.config === "tuned")
        .sort((a, b) => a.ns - b.ns)[0];
      rows.push([
        `dilute gas, 1,000 discs, ${gas.span} s`,
        `${ms(gas.chapgame.ns)}, ΔE/E ${sig(gas.chapgame.metrics.energyError)}`,
        best
          ? `fastest peer at 60 Hz (tuned): ${best.peer} ${ms(best.ns)}, ΔE/E ${sig(best.metrics.energyError)}`
          : dash,
        dash,
        dash,
      ]);
    }
    const gal = p.scenes.filter((x) => x.id.startsWith("galperin"));
    const digitsOk = (pred) => {
      let d = 0;
      for (const x of gal) if (pred(x)) d = Math.max(d, Number(x.id.split("-")[1]));
      return d;
    };
    const cg = digitsOk((x) => x.chapgame?.metrics && x.chapgame.metrics.collisions === x.exact.collisions);
    const peerBest = digitsOk((x) =>
      x.peers.some(
        (q) => q.metrics && q.metrics.collisions === x.exact.collisions && q.metrics.escaped === 0,
      ),
    );
    rows.push([
      "Galperin's billiard: most digits right (side-by-side run)",
      `${cg}`,
      `best peer: ${peerBest}`,
      dash,
      dash,
    ]);
    const bullets = p.scenes.filter((x) => x.id.startsWith("bullet"));
    const reflected = (m) => Boolean(m && m.escaped === 0 && m.finalError && m.finalError.position < 1e-3);
    const maxSpeed = (pred) => Math.max(0, ...bullets.filter(pred).map((x) => Number(x.id.split("-")[1])));
    rows.push([
      "thin wall: fastest disc reflected right (not through, end within 1e-3 of exact), units/s",
      sig(maxSpeed((x) => reflected(x.chapgame?.metrics))),
      `best peer: ${sig(maxSpeed((x) => x.peers.some((q) => reflected(q.metrics))))}`,
      dash,
      dash,
    ]);
    const cr = find("cradle");
    if (cr?.chapgame?.metrics) {
      const bestCr = cr.peers
        .filter((q) => q.metrics?.finalError)
        .sort((a, b) => a.metrics.finalError.position - b.metrics.finalError.position)[0];
      rows.push([
        "Newton's cradle: distance from the exact end state",
        sig(cr.chapgame.metrics.finalError?.position),
        bestCr
          ? `best peer: ${bestCr.peer} ${bestCr.config} ${bestCr.hz} Hz: ${sig(bestCr.metrics.finalError.position)}`
          : dash,
        dash,
        dash,
      ]);
    }
  }
  const push = r.stress?.galperinPush;
  if (push)
    rows.push([
      "Galperin's billiard pushed: first wrong digit count",
      push.firstWrong === null
        ? `none up to ${push.lastCorrect} digits`
        : `${push.firstWrong} (correct up to ${push.lastCorrect})`,
      dash,
      dash,
      dash,
    ]);
  return table(["benchmark", "chapgame", "comparison (same run)", "target", "status"], rows);
}

/**
 * Merge the rows of a separate `--push-digits` run (bench/results/galperin-push.json) that go beyond
 * what the main run measured; those rows say where they come from.
 */
function mergePush(results) {
  const file = join(ROOT, "bench", "results", "galperin-push.json");
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

export function generate(results, { root = ROOT } = {}) {
  if (!results.quick) mergePush(results);
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
  out.push(CAVEATS.map((c) => `- ${c}`).join("\n"));
  out.push("");
  const dir = join(root, "docs", "bench");
  mkdirSync(dir, { recursive: true });
  for (const f of readdirSync(dir)) if (f.endsWith(".svg")) rmSync(join(dir, f));
  for (const [f, text] of Object.entries(svgs)) writeFileSync(join(root, "docs", "bench", f), `${text}\n`);
  writeFileSync(join(root, "docs", "benchmarks.md"), `${out.join("\n")}\n`);
  writeFileSync(
    join(root, "docs", "benchmarks-headline.md"),
    `<!-- generated by npm run bench from ${results.file}; details in docs/benchmarks.md -->\n${head}\n\nMachine: ${results.machine.cpu}, ${results.machine.cores} cores, Node ${results.machine.node}${results.quick ? " (quick run)" : ""}.${speedProbeNote(results)} Details: [docs/benchmarks.md](docs/benchmarks.md).\n`,
  );
  // The README carries the same headline between markers, rewritten here (never typed by hand).
  const readme = join(root, "README.md");
  if (existsSync(readme)) {
    const text = readFileSync(readme, "utf8");
    const start = "<!-- bench-headline:start -->";
    const end = "<!-- bench-headline:end -->";
    const i = text.indexOf(start);
    const j = text.indexOf(end);
    if (i >= 0 && j > i) {
      const body = `${head}\n\nMachine: ${results.machine.cpu}, ${results.machine.cores} cores, Node ${results.machine.node}${results.quick ? " (quick run)" : ""}; ${results.date}.${speedProbeNote(results)} Details: [docs/benchmarks.md](docs/benchmarks.md).`;
      writeFileSync(readme, `${text.slice(0, i + start.length)}\n${body}\n${text.slice(j)}`);
    }
  }
  return {
    files: [
      "docs/benchmarks.md",
      "docs/benchmarks-headline.md",
      ...Object.keys(svgs).map((f) => `docs/bench/${f}`),
    ],
  };
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const file = process.argv[2] ?? join(ROOT, "bench", "results", "latest.json");
  const r = generate(JSON.parse(readFileSync(file, "utf8")));
  console.log(`wrote ${r.files.length} files`);
}
