/**
 * Engine section, mixed radii: events/s of a 10 % gas of 10,000 discs of radius 1 around one heavy
 * disc of radius 1 (no big disc: the baseline), 5, 20 or 100 (bench/scenes/bigDisc.mjs), and the
 * share of events the big disc takes part in; then (`manyRows`) 10 % gases of 10,000 discs with
 * many large ones or radii spread over a range (bench/scenes/polydisperse.mjs). The grid puts each
 * disc in the finest of its levels whose cells fit it, when levels pay (sim/gridCost.ts). Rows run
 * one after the other in this process, each on a fresh World after a warm-up of 2 events per disc,
 * then `runs` timed batches (median).
 */
import { gc, nowNs, timedRuns } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { bigDiscGas } from "../scenes/bigDisc.mjs";
import { polydisperseGas, RADIUS_LAWS } from "../scenes/polydisperse.mjs";

export const BIG_RADII = [1, 5, 20, 100];

/** Events/s of `world` over `runs` timed batches of `batch` events (median), after a warm-up. */
function rate(world, warmup, batch, runs, onEvent) {
  world.advance({ maxEvents: warmup });
  const t = timedRuns(
    () => {
      const a = nowNs();
      world.advance({ maxEvents: batch }, onEvent);
      return nowNs() - a;
    },
    { runs, budgetNs: 60e9 },
  );
  return { runs: t.runs, eventsPerSecond: batch / (t.medianNs / 1e9) };
}

export function mixedRadii({ quick, engine, log }) {
  const n = 10000;
  const batch = quick ? 30000 : 200000;
  const runs = quick ? 1 : 3;
  const rows = [];
  for (const bigR of BIG_RADII) {
    const scene = bigDiscGas({ n, bigR });
    try {
      gc();
      let bigEvents = 0;
      let events = 0;
      const onEvent = (e) => {
        events++;
        if (e.a === "big" || e.b === "big") bigEvents++;
      };
      const r = rate(buildWorld(engine, scene), 2 * n, batch, runs, onEvent);
      const row = {
        bigR,
        n,
        description: scene.description,
        batch,
        ...r,
        bigEventShare: bigEvents / Math.max(1, events),
      };
      rows.push(row);
      log(`  mixed radii, big r = ${bigR}: ${Math.round(row.eventsPerSecond)} events/s`);
    } catch (e) {
      log(`  mixed radii, big r = ${bigR}: ERROR ${e.message}`);
      rows.push({ bigR, n, error: String(e.message ?? e) });
    }
  }
  const manyRows = [];
  for (const law of Object.keys(RADIUS_LAWS)) {
    try {
      gc();
      const scene = polydisperseGas({ n, law });
      const r = rate(buildWorld(engine, scene), 2 * n, batch, runs);
      manyRows.push({ law, n, description: scene.description, batch, ...r });
      log(`  mixed radii, ${law}: ${Math.round(r.eventsPerSecond)} events/s`);
    } catch (e) {
      log(`  mixed radii, ${law}: ERROR ${e.message}`);
      manyRows.push({ law, n, error: String(e.message ?? e) });
    }
  }
  return { rows, manyRows };
}
