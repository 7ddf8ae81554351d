/**
 * Engine section, a scene built one action per call at successive instants: N discs applied with
 * Timeline.apply one per call at t = 0, 0.01, 0.02, ... (an editor adding discs at different
 * times, a game spawning a body every frame), with history and without, at N = 1,000 to 8,000
 * (quick: to 4,000). Two scenes: discs at rest on a square lattice (g = 0, nothing happens between
 * instants), and discs thrown at random under friction (mu 0.2, 1 to 2.4 units/s) on a wider
 * lattice, which meet their neighbours now and then (collisions and stops between instants).
 * Each row: the total time and the microseconds per apply; the ratio of the per-apply time at the
 * largest N to the smallest says how it scales (1 = linear; it was about N_max / N_min before the
 * scene check asked the World for the bodies near a disc and the keyframe after an instant became
 * a delta, session 26). Each time is the median of `runs` fresh builds.
 * Then reads over such a history (the thrown scene, with history, N = 2,000 and 8,000; quick: 2,000),
 * where every instant's keyframe is a delta of the one before (keyframeChain.ts): stateAt and
 * bodyArraysAt(t, into) at `reads` times spread over it, backwards (each read loads its keyframe)
 * and forwards (playback), and path() of three discs over the whole history; each figure is the
 * median of `passes` passes' times per call, the ways alternating (readWays gives them, for
 * comparing two builds in one process).
 * About 20 s (6 s with --quick). `node bench/engine/instants.mjs [--quick]` runs it alone.
 */
import { fileURLToPath } from "node:url";
import { loadEngine } from "../lib/engine.mjs";
import { lcg } from "../lib/lcg.mjs";
import { gc, median, nowNs } from "../lib/timing.mjs";

/** Spacing of the lattice (discs of radius 1): at rest, and thrown (a thrown disc slides at most
 *  1.5 under friction: neighbours meet, and a spot is still free when its disc comes). */
const SPACING = { resting: 3, thrown: 4 };

/** The i-th action of a scene of n discs at time t (`rand`: the thrown scene's generator). */
function discAction(scene, i, n, t, rand) {
  const side = Math.ceil(Math.sqrt(n));
  const base = { time: t, type: "addBody", id: `d${i}`, r: 1, m: 1 };
  const x = (i % side) * SPACING[scene];
  const y = Math.floor(i / side) * SPACING[scene];
  if (scene === "resting") return { ...base, x, y };
  const angle = 2 * Math.PI * rand();
  const speed = 1 + 1.4 * rand();
  return { ...base, x, y, mu: 0.2, v: [speed * Math.cos(angle), speed * Math.sin(angle)] };
}

/** Milliseconds to apply n discs one per call at successive instants (median of `runs`). */
function build(engine, scene, n, history, runs) {
  const times = [];
  let last;
  for (let k = 0; k < runs; k++) {
    const rand = lcg(7);
    const actions = Array.from({ length: n }, (_, i) => discAction(scene, i, n, i * 0.01, rand));
    gc();
    const tl = new engine.Timeline({ g: scene === "resting" ? 0 : 9.81, history });
    const a = nowNs();
    for (const act of actions) tl.apply(act); // none is refused: an error ends the section
    times.push((nowNs() - a) / 1e6);
    last = tl;
  }
  return { ms: median(times), events: last.counts() };
}

/** A history of n thrown discs built one per instant and the reads timed on it (see the header):
 *  { tl, ways: [{ name, order, calls, run }] }, run() making `calls` calls. */
export function readWays(engine, n, reads) {
  const rand = lcg(7);
  const tl = new engine.Timeline({ g: 9.81, history: true });
  for (let i = 0; i < n; i++) tl.apply(discAction("thrown", i, n, i * 0.01, rand));
  const h = tl.horizon;
  const forwards = Array.from({ length: reads }, (_, k) => (h * (k + 0.5)) / reads);
  const backwards = [...forwards].reverse();
  const ids = [0, n >> 1, n - 1].map((i) => `d${i}`);
  let into;
  const way = (name, order, times, read) => ({
    name,
    order,
    calls: times.length,
    run: () => {
      for (const t of times) read(t);
    },
  });
  return {
    tl,
    ways: [
      way("stateAt", "backwards", backwards, (t) => tl.stateAt(t)),
      way("stateAt", "forwards", forwards, (t) => tl.stateAt(t)),
      way("bodyArraysAt", "backwards", backwards, (t) => (into = tl.bodyArraysAt(t, into))),
      way("bodyArraysAt", "forwards", forwards, (t) => (into = tl.bodyArraysAt(t, into))),
      way("path", "whole history", ids, (id) => tl.path(id)),
    ],
  };
}

/** Milliseconds per call of each of readWays' ways at each N (see the header). */
function readRows(engine, sizes, reads, passes) {
  return sizes.map((n) => {
    const { tl, ways } = readWays(engine, n, reads);
    const times = ways.map(() => []);
    for (let p = -1; p < passes; p++)
      ways.forEach((w, k) => {
        gc();
        const a = nowNs();
        w.run();
        if (p >= 0) times[k].push((nowNs() - a) / 1e6 / w.calls); // pass -1 warms up
      });
    return {
      n,
      events: tl.eventCount,
      historyBytes: tl.historyBytes(),
      ways: ways.map((w, k) => ({ name: w.name, order: w.order, ms: median(times[k]) })),
    };
  });
}

export function instants({ quick, engine, log }) {
  try {
    const sizes = quick ? [1000, 2000, 4000] : [1000, 2000, 4000, 8000];
    const runs = quick ? 1 : 3;
    const rows = [];
    for (const scene of ["resting", "thrown"])
      for (const history of [true, false]) {
        const row = { scene, history, points: [] };
        build(engine, scene, 500, history, 1); // warm-up
        for (const n of sizes) {
          const { ms, events } = build(engine, scene, n, history, runs);
          const collisions = events.bodyBody + events.bodyLine + events.bodyPoint;
          row.points.push({ n, ms, usPerApply: (ms * 1000) / n, collisions, stops: events.stop });
        }
        const first = row.points[0];
        const lastPoint = row.points[row.points.length - 1];
        row.scaling = lastPoint.usPerApply / first.usPerApply;
        rows.push(row);
        log(
          `  one per instant, ${scene}, history ${history}: ${row.points.map((p) => `N=${p.n} ${p.ms.toFixed(0)} ms`).join(", ")} (per apply ×${row.scaling.toFixed(2)} from N=${first.n} to ${lastPoint.n})`,
        );
      }
    const reads = { count: 40, passes: quick ? 3 : 5 };
    reads.rows = readRows(engine, quick ? [2000] : [2000, 8000], reads.count, reads.passes);
    for (const r of reads.rows)
      log(
        `  reads over one per instant, N=${r.n}: ${r.ways.map((w) => `${w.name} ${w.order} ${w.ms.toFixed(3)} ms`).join(", ")}`,
      );
    return { runs, dt: 0.01, rows, reads };
  } catch (e) {
    log(`  one per instant: ERROR ${e.message}`);
    return { error: String(e.message ?? e) };
  }
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { engine } = await loadEngine();
  const quick = process.argv.includes("--quick");
  const out = instants({ quick, engine, log: (m) => console.error(m) });
  process.stdout.write(`${JSON.stringify(out, null, 1)}\n`);
}
