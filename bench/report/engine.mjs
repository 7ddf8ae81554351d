/**
 * Report section 3, the engine: dilute-gas scaling against N (table, targets, the stripped loops'
 * ceilings, scaling.svg), Galperin's billiard at 7 digits, then the optimisation switches
 * (ablations.mjs), mixed radii (mixedRadii.mjs), obstacle-heavy scenes (obstacles.mjs), the
 * all-pairs reference comparison and the Timeline (timeline.mjs).
 * engineSection(results.engine, out, svgs) appends markdown lines to `out` and SVG texts to `svgs`.
 */
import { ablationsBlock } from "./ablations.mjs";
import { bulkReadsBlock } from "./bulkReads.mjs";
import { galperinTarget, int, ms, numberWord, sig, status, table } from "./format.mjs";
import { instantsBlock } from "./instants.mjs";
import { mixedRadiiBlock } from "./mixedRadii.mjs";
import { obstaclesBlock } from "./obstacles.mjs";
import { plot } from "./svg.mjs";
import { timelineBlock } from "./timeline.mjs";

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
  // The JavaScript loop with code shared by instances, as a library's always is (a program makes
  // several Worlds: a Timeline's keyframes, clones); the one-instance rate is only reported.
  judge(
    "events/s",
    sc.minimalEventsPerSecondAt1e4,
    sc.wasmEventsPerSecondAt1e4,
    (v) => v >= t.eventsPerSecondAt1e4,
  );
  judge("cost-ratio", sc.minimalCostRatio1e5over1e3, sc.wasmCostRatio1e5over1e3, (v) => v <= t.costRatio);
  return said.join(" ");
}

export function engineSection(e, out, svgs) {
  if (!e) return;
  out.push("## 3. Engine scaling, Galperin 7 digits, optimisations\n");
  if (e.error) {
    out.push(`Not measured: ${e.error}\n`);
    return;
  }
  const sc = e.scaling;
  const perN = sc.processesPerN == null ? "several" : numberWord(sc.processesPerN);
  out.push(
    `Dilute gas (10 % packing, r = 1, speed 10, box walls), timed batches of events after a warm-up that leaves the grid start; events/s = batch / median batch time. Each N runs in fresh Node processes (no JIT state from other rows or sections; the engine and both loops compiled first on a small gas), ${perN} per N in this run, in rounds of one process per N (so a drift of the machine's speed falls on every N alike, not on N = 10⁵, measured last), with the median kept, because at 10⁵ discs one process's rate differs from the next by up to 30 % (memory placement) while its own batches agree; the per-process rates are in latest.json. Memory per body = growth of the JS heap plus ArrayBuffer memory (where typed arrays live) when building and preparing (grid and event queue) copies of the world holding at least 10⁵ bodies in all, / bodies; the per-body typed arrays grow by 1.5 and are trimmed to the bodies plus 1/16 when the world is prepared (packages/engine/src/sim/bodyStore.ts), so it varies little with N. Heap allocated per event = bytes the JS heap allocates over up to 10⁵ further events, short-lived objects included (V8's sampling heap profiler, after the timed batches): doubles that cross a call V8 does not inline are boxed on the heap, and this column shows how many remain.\n`,
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
        "minimal loop, JS, one instance, events/s",
        "minimal loop, WebAssembly, events/s",
        "memory per body, bytes",
        "heap allocated per event, bytes",
        "build time",
      ],
      sc.rows.map((r) =>
        r.error
          ? [int(r.n), `error: ${r.error}`, "", "", "", "", "", "", "", "", ""]
          : [
              int(r.n),
              int(r.batch),
              r.runs,
              int(r.eventsPerSecond),
              sig(r.nsPerEvent),
              r.minimalEventsPerSecond === undefined ? "—" : int(r.minimalEventsPerSecond),
              r.minimalOneInstanceEventsPerSecond == null ? "—" : int(r.minimalOneInstanceEventsPerSecond),
              r.wasmError
                ? `error: ${r.wasmError}`
                : r.wasmEventsPerSecond == null
                  ? "—"
                  : int(r.wasmEventsPerSecond),
              int(r.heapBytesPerBody),
              r.allocatedBytesPerEvent == null ? "—" : int(r.allocatedBytesPerEvent),
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
      `- Ceilings: the same algorithm with every product feature stripped (\`bench/engine/minimalGas.mjs\`: no API, ids, tie order, friction, gravity, lines or reports) reaches ${int(sc.minimalEventsPerSecondAt1e4)} events/s at N = 10,000 in JavaScript and a cost ratio of ${sig(sc.minimalCostRatio1e5over1e3)} between N = 100,000 and 1,000, timed after another instance in its process (its code shared by instances, as the engine's always is).${sc.minimalOneInstanceEventsPerSecondAt1e4 == null ? "" : ` As the only instance in its process, V8 specialises its code to that instance's arrays and sizes: ${int(sc.minimalOneInstanceEventsPerSecondAt1e4)} events/s${sc.minimalOneInstanceCostRatio1e5over1e3 == null ? "" : ` and a ratio of ${sig(sc.minimalOneInstanceCostRatio1e5over1e3)}`}, the best plain JavaScript does here, but not what a library's code gets.`}${wasm} ${ceilingVerdict(sc)}`,
    );
  }
  const g = e.galperin7;
  if (g.error) out.push(`- Galperin's billiard, 7 digits: error: ${g.error}.`);
  else
    out.push(
      `- Galperin's billiard, 7 digits: ${int(g.count)} collisions (exact ${int(g.expected)}${g.correct ? ", correct" : ", WRONG"}) in ${sig(g.seconds)} s${g.secondsPerProcess ? ` (median of ${numberWord(g.secondsPerProcess.length)} fresh process${g.secondsPerProcess.length === 1 ? "" : "es"}, each warmed up on 5 digits: ${g.secondsPerProcess.map((x) => sig(x)).join(", ")} s)` : ""} (target < ${galperinTarget(g)} s): ${status(g.correct && g.seconds < galperinTarget(g))}.`,
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
  ablationsBlock(e, out);
  mixedRadiiBlock(e, out);
  obstaclesBlock(e, out);
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
  timelineBlock(e, out);
  bulkReadsBlock(e, out);
  instantsBlock(e, out);
}
