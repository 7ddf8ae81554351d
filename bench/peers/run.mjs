/**
 * Section "peers": the same engine-neutral scenes in chapgame and in matter-js, planck and rapier
 * at fixed steps, each peer in two configurations ("defaults": the scene's physics only;
 * "tuned": thresholds off, CCD/bullets on). Every row, chapgame's and each peer's alike (timeRow):
 * a forced garbage collection, a metrics pass, warm-up passes until the times settle, then timed
 * passes; `ns` is their median, with their spread and every pass's time beside it in the JSON.
 */
import { PASS_LIMITS, settledPasses, spreadOf } from "../lib/settledPasses.mjs";
import { gc, nowNs } from "../lib/timing.mjs";
import { breakShot } from "../scenes/breakShot.mjs";
import { bullet } from "../scenes/bullet.mjs";
import { cradle } from "../scenes/cradle.mjs";
import { galperin } from "../scenes/galperin.mjs";
import { gas } from "../scenes/gas.mjs";
import { runChapgame } from "./chapgame.mjs";
import { drivePeer } from "./drive.mjs";
import * as matter from "./matter.mjs";
import * as planck from "./planck.mjs";
import * as rapier from "./rapier.mjs";

export const PEERS = [matter, planck, rapier];
const CONFIGS = ["tuned", "defaults"];
const BUDGET_NS = 3e9;
// A quick run (about 62 s in all) stays short: at most one warm-up pass and one timed pass per row.
const QUICK_LIMITS = { ...PASS_LIMITS, maxWarmup: 1, minRuns: 1, maxRuns: 1 };

export function peerScenes(quick) {
  const gasSpan = quick ? 0.5 : 2;
  const digits = quick ? [1, 2, 3, 5] : [1, 2, 3, 4, 5, 6, 7, 8];
  const speeds = quick ? [10, 1e3, 1e6] : [10, 1e2, 1e3, 1e4, 1e5, 1e6];
  return [
    gas({ n: 1000, packing: 0.1, speed: 10, seed: 1, span: gasSpan }),
    gas({ n: 1000, packing: 0.4, speed: 10, seed: 2, span: gasSpan / 2 }),
    // the peers already fail at 3 digits; beyond 6 only chapgame runs (the peers' cost grows, not their answers)
    ...digits.map((d) => (d > 6 ? { ...galperin(d), peersSkipped: "not run beyond 6 digits" } : galperin(d))),
    cradle(),
    ...speeds.map((v) => bullet(v)),
    breakShot(),
  ];
}

/**
 * One row's timing, the same for chapgame and every peer: the garbage of earlier rows collected
 * first (never between the passes: a forced full collection deoptimises what the warm-up compiled),
 * then metricsPass() (returns { ns, ... }), then `pass` (returns its own ns) settled and repeated.
 * A metrics pass over BUDGET_NS is the row's one sample. Returns { m, timing } where timing holds
 * the JSON fields: ns (median), runs, minNs, q1Ns, q3Ns, maxNs, passesNs, warmup, metricsPassNs.
 */
function timeRow(metricsPass, pass, quick) {
  gc();
  const m = metricsPass();
  const t =
    m.ns > BUDGET_NS
      ? { ...spreadOf([m.ns]), runs: 1, allNs: [m.ns], warmup: { passes: 0, allNs: [], settled: null } }
      : settledPasses(pass, { alreadyNs: m.ns, limits: quick ? QUICK_LIMITS : PASS_LIMITS });
  const { medianNs, runs, allNs, warmup, ...spread } = t;
  return { m, timing: { ns: medianNs, runs, ...spread, passesNs: allNs, warmup, metricsPassNs: m.ns } };
}

function chapgameEntry(engine, scene, quick, log) {
  if (typeof engine?.World !== "function") return { error: "World is not exported by @chapgame/engine yet" };
  try {
    const { m, timing } = timeRow(
      () => runChapgame(engine, scene, { withMetrics: true }),
      () => runChapgame(engine, scene).ns,
      quick,
    );
    const ms = (ns) => (ns / 1e6).toFixed(2);
    log(
      `  chapgame ${scene.id}: ${ms(timing.ns)} ms (${ms(timing.minNs)}–${ms(timing.maxNs)}, ${timing.runs} ${timing.runs === 1 ? "pass" : "passes"} after ${timing.warmup.passes} warm-up), ${m.events} events`,
    );
    return { ...timing, events: m.events, metrics: m.metrics };
  } catch (e) {
    log(`  chapgame ${scene.id}: ERROR ${e.message}`);
    return { error: String(e.message ?? e) };
  }
}

export async function runPeers({ quick, engine, log }) {
  for (const p of PEERS) await p.init();
  const rates = quick ? [60, 240] : [60, 240, 960];
  const settings = {};
  const scenes = [];
  for (const scene of peerScenes(quick)) {
    const sceneStart = nowNs();
    const entry = {
      id: scene.id,
      title: scene.title,
      description: scene.description,
      bodies: scene.bodies.length,
      span: scene.span,
      exact: scene.exact
        ? { collisions: scene.exact.collisions ?? null, final: Boolean(scene.exact.final) }
        : null,
      chapgame: chapgameEntry(engine, scene, quick, log),
      peers: [],
      peersSkipped: scene.peersSkipped ?? null,
    };
    for (const p of scene.peersSkipped ? [] : PEERS) {
      for (const config of CONFIGS) {
        const tuned = config === "tuned";
        for (const hz of rates) {
          if (quick && config === "defaults" && hz !== rates[0]) continue; // quick: defaults at 60 Hz only
          try {
            // The metrics pass times step() only; over BUDGET_NS it is the row's one sample.
            const { m, timing } = timeRow(
              () => drivePeer(p, scene, { hz, tuned, withMetrics: true }),
              () => drivePeer(p, scene, { hz, tuned }).ns,
              quick,
            );
            settings[p.name] ??= { version: p.version };
            settings[p.name][config] ??= m.settings;
            entry.peers.push({ peer: p.name, config, hz, steps: m.steps, ...timing, metrics: m.metrics });
          } catch (e) {
            entry.peers.push({ peer: p.name, config, hz, error: String(e.message ?? e) });
          }
        }
      }
    }
    scenes.push(entry);
    log(`peers: ${scene.id} done in ${((nowNs() - sceneStart) / 1e9).toFixed(1)} s`);
  }
  return { rates, configs: CONFIGS, passLimits: quick ? QUICK_LIMITS : PASS_LIMITS, settings, scenes };
}
