/**
 * Engine section, mixed radii: events/s of a 10 % gas of 10,000 discs of radius 1 around one heavy
 * disc of radius 1 (no big disc: the baseline), 5, 20 or 100 (bench/scenes/bigDisc.mjs), and the
 * share of events the big disc takes part in. The grid's cells are sized for the radius of the
 * bodies in them; up to GRID_BIG_BODIES_MAX discs far larger than the rest are kept out of the cells
 * and tested against every body instead, so a big disc costs its own events O(N) and the others
 * nothing. Rows run one after the other in this process, each on a fresh World after a warm-up of
 * 2 events per disc, then `runs` timed batches (median).
 */
import { gc, nowNs, timedRuns } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { bigDiscGas } from "../scenes/bigDisc.mjs";

export const BIG_RADII = [1, 5, 20, 100];

export function mixedRadii({ quick, engine, log }) {
  const n = 10000;
  const batch = quick ? 30000 : 200000;
  const runs = quick ? 1 : 3;
  const rows = [];
  for (const bigR of BIG_RADII) {
    const scene = bigDiscGas({ n, bigR });
    try {
      gc();
      const world = buildWorld(engine, scene);
      world.advance({ maxEvents: 2 * n });
      let bigEvents = 0;
      let events = 0;
      const onEvent = (e) => {
        if (e.a === "big" || e.b === "big") bigEvents++;
      };
      const t = timedRuns(
        () => {
          const a = nowNs();
          events += world.advance({ maxEvents: batch }, onEvent).events;
          return nowNs() - a;
        },
        { runs, budgetNs: 60e9 },
      );
      const row = {
        bigR,
        n,
        description: scene.description,
        batch,
        runs: t.runs,
        eventsPerSecond: batch / (t.medianNs / 1e9),
        bigEventShare: bigEvents / Math.max(1, events),
      };
      rows.push(row);
      log(`  mixed radii, big r = ${bigR}: ${Math.round(row.eventsPerSecond)} events/s`);
    } catch (e) {
      log(`  mixed radii, big r = ${bigR}: ERROR ${e.message}`);
      rows.push({ bigR, n, error: String(e.message ?? e) });
    }
  }
  return { rows };
}
