/**
 * The report's headline table (docs/benchmarks.md, docs/benchmarks-headline.md and the README's
 * block): one row per headline number, each beside a comparison measured in the same run, its target
 * and met/missed. headline(results) returns the markdown table.
 */
import { dash, galperinTarget, int, msRange, sig, status, table } from "./format.mjs";

export function headline(r) {
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
        : `stripped loop: JS ${int(sc.minimalEventsPerSecondAt1e4)}${sc.minimalOneInstanceEventsPerSecondAt1e4 == null ? "" : ` (one instance ${int(sc.minimalOneInstanceEventsPerSecondAt1e4)})`}${sc.wasmEventsPerSecondAt1e4 == null ? "" : `, WebAssembly ${int(sc.wasmEventsPerSecondAt1e4)}`}`,
      `≥ ${int(sc.targets.eventsPerSecondAt1e4)}`,
      status(
        sc.eventsPerSecondAt1e4 === null ? null : sc.eventsPerSecondAt1e4 >= sc.targets.eventsPerSecondAt1e4,
      ),
    ]);
    rows.push([
      "cost per event, N = 100,000 vs 1,000",
      `${sig(sc.costRatio1e5over1e3)}×`,
      sc.minimalCostRatio1e5over1e3 == null
        ? dash
        : `stripped loop: JS ${sig(sc.minimalCostRatio1e5over1e3)}×${sc.minimalOneInstanceCostRatio1e5over1e3 == null ? "" : ` (one instance ${sig(sc.minimalOneInstanceCostRatio1e5over1e3)}×)`}${sc.wasmCostRatio1e5over1e3 == null ? "" : `, WebAssembly ${sig(sc.wasmCostRatio1e5over1e3)}×`}`,
      `≤ ${sc.targets.costRatio}×`,
      status(sc.costRatio1e5over1e3 === null ? null : sc.costRatio1e5over1e3 <= sc.targets.costRatio),
    ]);
    const g = e.galperin7;
    rows.push([
      "Galperin 7 digits (3,141,592 collisions)",
      g.error ? `error` : `${int(g.count)} in ${sig(g.seconds)} s`,
      dash,
      `< ${galperinTarget(g)} s, exact count`,
      status(g.error ? false : g.correct && g.seconds < galperinTarget(g)),
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
        `${msRange(gas.chapgame)}, ΔE/E ${sig(gas.chapgame.metrics.energyError)}`,
        best
          ? `fastest peer at 60 Hz (tuned): ${best.peer} ${msRange(best)}, ΔE/E ${sig(best.metrics.energyError)}`
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
