/**
 * Section "peers": the same engine-neutral scenes in chapgame and in matter-js, planck and rapier
 * at fixed steps, each peer in two configurations ("defaults": the scene's physics only;
 * "tuned": thresholds off, CCD/bullets on). Per run: a metrics pass (also the warm-up), then the
 * median of several timed passes.
 */
import { gc, nowNs, timedRuns } from "../lib/timing.mjs";
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

function chapgameEntry(engine, scene, runs, log) {
  if (typeof engine?.World !== "function") return { error: "World is not exported by @chapgame/engine yet" };
  try {
    const m = runChapgame(engine, scene, { withMetrics: true });
    gc();
    const t =
      m.ns > BUDGET_NS
        ? { medianNs: m.ns, runs: 1 }
        : timedRuns(() => runChapgame(engine, scene).ns, { runs, budgetNs: BUDGET_NS });
    log(`  chapgame ${scene.id}: ${(t.medianNs / 1e6).toFixed(2)} ms, ${m.events} events`);
    return { ns: t.medianNs, runs: t.runs, events: m.events, metrics: m.metrics };
  } catch (e) {
    log(`  chapgame ${scene.id}: ERROR ${e.message}`);
    return { error: String(e.message ?? e) };
  }
}

export async function runPeers({ quick, engine, log }) {
  for (const p of PEERS) await p.init();
  const rates = quick ? [60, 240] : [60, 240, 960];
  const runs = quick ? 1 : 3;
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
      chapgame: chapgameEntry(engine, scene, runs, log),
      peers: [],
      peersSkipped: scene.peersSkipped ?? null,
    };
    for (const p of scene.peersSkipped ? [] : PEERS) {
      for (const config of CONFIGS) {
        const tuned = config === "tuned";
        for (const hz of rates) {
          if (quick && config === "defaults" && hz !== rates[0]) continue; // quick: defaults at 60 Hz only
          try {
            const m = drivePeer(p, scene, { hz, tuned, withMetrics: true });
            settings[p.name] ??= { version: p.version };
            settings[p.name][config] ??= m.settings;
            gc();
            // Short runs: the metrics pass is the warm-up, then up to `runs` timed passes. Long runs
            // (over the budget): the metrics pass (which times step() only) is the one sample.
            const t =
              m.ns > BUDGET_NS
                ? { medianNs: m.ns, runs: 1 }
                : timedRuns(() => drivePeer(p, scene, { hz, tuned }).ns, { runs, budgetNs: BUDGET_NS });
            entry.peers.push({
              peer: p.name,
              config,
              hz,
              steps: m.steps,
              ns: t.medianNs,
              runs: t.runs,
              metrics: m.metrics,
            });
          } catch (e) {
            entry.peers.push({ peer: p.name, config, hz, error: String(e.message ?? e) });
          }
        }
      }
    }
    scenes.push(entry);
    log(`peers: ${scene.id} done in ${((nowNs() - sceneStart) / 1e9).toFixed(1)} s`);
  }
  return { rates, configs: CONFIGS, settings, scenes };
}
