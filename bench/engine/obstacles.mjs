/**
 * Engine section, obstacle-heavy scenes (bench/scenes/obstacles.mjs): a few discs in mazes of 100
 * to 10,000 segments, and balls falling through Galton boards of 1,000 and 5,000 point pegs. The
 * grid is laid out over the obstacles when that pays (sim/broadPhase.ts, sim/gridCost.ts), so the
 * cost per event should barely grow with the number of obstacles. Each row: a fresh World, a
 * warm-up, then `runs` timed batches (median); beside it the same scene with `broadPhase: false`
 * (every prediction tests every body, segment and point) over a smaller batch after a short warm-up,
 * and whether the two Worlds are in the same state after those events, bit for bit. Each row also
 * times the scene's build, ready to simulate: a World, every wall, point and disc added through the
 * public API, then `advance({ maxEvents: 0 })` (the grid laid out, every obstacle registered in its
 * cells, every disc predicted); the median of the row's three builds (the timed World, and the two
 * compared with and without the grid), and that per obstacle, which should not grow with them.
 *
 * `node --expose-gc bench/engine/obstacles.mjs [--quick]` runs the rows alone and prints them.
 */
import { fileURLToPath } from "node:url";
import { loadEngine } from "../lib/engine.mjs";
import { gc, nowNs, timedRuns } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { galton, maze } from "../scenes/obstacles.mjs";

/** The rows: scene builders with the parameters they are run at. */
export const OBSTACLE_ROWS = [
  { kind: "maze", discs: 8, obstacles: 100 },
  { kind: "maze", discs: 8, obstacles: 1000 },
  { kind: "maze", discs: 8, obstacles: 10000 },
  { kind: "maze", discs: 40, obstacles: 10000 },
  { kind: "galton", discs: 5, obstacles: 1000 },
  { kind: "galton", discs: 5, obstacles: 5000 },
];

function sceneOf(row) {
  return row.kind === "maze"
    ? maze({ discs: row.discs, segments: row.obstacles })
    : galton({ balls: row.discs, pegs: row.obstacles });
}

/** The median of a few numbers. */
function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
}

/** Each body's state, for the bit-for-bit comparison of the two Worlds. */
const stateOf = (world) => JSON.stringify(world.bodies());

function measureRow(engine, row, { warmup, batch, runs, offWarmup, offBatch }) {
  const scene = sceneOf(row);
  const builds = [];
  /** The scene built and ready to simulate (timed: see the header). */
  const built = (worldOptions) => {
    gc();
    const a = nowNs();
    const w = buildWorld(engine, scene, worldOptions);
    w.advance({ maxEvents: 0 });
    builds.push(nowNs() - a);
    return w;
  };
  const world = built();
  world.advance({ maxEvents: warmup });
  const t = timedRuns(
    () => {
      const a = nowNs();
      world.advance({ maxEvents: batch });
      return nowNs() - a;
    },
    { runs, budgetNs: 60e9 },
  );
  const grid = world.grid;
  // The same scene without the grid (a short warm-up of its own, then offBatch events timed), and
  // with it over as many events.
  const on = built();
  on.advance({ maxEvents: offWarmup + offBatch });
  const off = built({ optimizations: { broadPhase: false } });
  off.advance({ maxEvents: offWarmup });
  const a = nowNs();
  const offEvents = off.advance({ maxEvents: offBatch }).events;
  const offNs = nowNs() - a;
  return {
    kind: row.kind,
    discs: row.discs,
    obstacles: row.obstacles,
    description: scene.description,
    batch,
    runs: t.runs,
    eventsPerSecond: batch / (t.medianNs / 1e9),
    usPerEvent: t.medianNs / 1e3 / batch,
    cells: grid ? grid.nx * grid.ny : null,
    cellSide: grid ? grid.w : null,
    offBatch: offEvents,
    offUsPerEvent: offNs / 1e3 / offEvents,
    sameAsOff: stateOf(on) === stateOf(off),
    buildMs: median(builds) / 1e6,
    buildUsPerObstacle: median(builds) / 1e3 / row.obstacles,
  };
}

export function obstacleRows({ quick, engine, log }) {
  const opts = quick
    ? { warmup: 10000, batch: 20000, runs: 1, offWarmup: 100, offBatch: 300 }
    : { warmup: 10000, batch: 50000, runs: 3, offWarmup: 200, offBatch: 1000 };
  const rows = [];
  for (const row of OBSTACLE_ROWS) {
    const label = `${row.kind} ${row.discs} discs, ${row.obstacles} obstacles`;
    try {
      const r = measureRow(engine, row, opts);
      rows.push(r);
      log(
        `  ${label}: ${r.usPerEvent.toFixed(2)} µs/event (grid of ${r.cells} cells), ${r.offUsPerEvent.toFixed(1)} without the grid${r.sameAsOff ? "" : ", DIFFERENT STATE"}; built in ${r.buildMs.toFixed(1)} ms (${r.buildUsPerObstacle.toFixed(2)} µs per obstacle)`,
      );
    } catch (e) {
      log(`  ${label}: ERROR ${e.message}`);
      rows.push({ ...row, error: String(e.message ?? e) });
    }
  }
  return { rows };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { engine } = await loadEngine();
  const quick = process.argv.includes("--quick");
  const out = obstacleRows({ quick, engine, log: (m) => console.log(m) });
  console.log(JSON.stringify(out, null, 1));
}
