/**
 * Section "engine": chapgame alone.
 * - scaling (scaling.mjs, one process per N): events/s of the dilute gas against N, the cost
 *   ratio N = 1e5 vs 1e3 and events/s at N = 1e4, beside the stripped JS and WebAssembly loops.
 * - galperin7 (galperin7.mjs, fresh processes): Galperin's billiard with 7 digits run to idle
 *   (target < 2 s, 3,141,592 collisions).
 * - reference: the fast engine against the tests' all-pairs reference simulator (reference.mjs).
 * - ablations (ablations.mjs, one process per configuration): each World `optimizations` switch
 *   off in turn, on the scene where it should matter; same events (checked), time ratio off/on.
 * - mixedRadii (mixedRadii.mjs): a gas of 10,000 discs around one disc of radius 1 to 100.
 * - obstacles (obstacles.mjs): a few discs in mazes of 100 to 10,000 segments, balls through Galton
 *   boards of 1,000 and 5,000 pegs; with and without the grid.
 * - timeline: stateAt latency and history bytes per event, when the engine exports Timeline.
 * - bulkReads (bulkReads.mjs): every body of 20,000 read as objects and as arrays (BodyArrays).
 * - instants (instants.mjs): 1,000 to 8,000 discs applied one per call at successive instants, and
 *   stateAt, bodyArraysAt and path() over such a history (N = 2,000 and 8,000).
 */

import { lcg } from "../lib/lcg.mjs";
import { nowNs } from "../lib/timing.mjs";
import { gas } from "../scenes/gas.mjs";
import { ablations } from "./ablations.mjs";
import { bulkReads } from "./bulkReads.mjs";
import { galperinRun } from "./galperin7.mjs";
import { instants } from "./instants.mjs";
import { mixedRadii } from "./mixedRadii.mjs";
import { obstacleRows } from "./obstacles.mjs";

import { againstReference } from "./reference.mjs";
import { scaling } from "./scaling.mjs";

export function timeline({ quick, engine, log }) {
  if (typeof engine.Timeline !== "function")
    return { error: "Timeline is not exported by @chapgame/engine yet" };
  try {
    const n = 1000;
    const scene = gas({ n, packing: 0.1, speed: 10, seed: 3, span: quick ? 5 : 20 });
    const tl = new engine.Timeline({ g: 0 });
    for (const w of scene.walls)
      tl.apply({ time: 0, type: "addLine", id: w.id, p1: w.p1, p2: w.p2, kind: w.kind });
    for (const b of scene.bodies)
      tl.apply({
        time: 0,
        type: "addBody",
        id: b.id,
        x: b.x,
        y: b.y,
        r: b.r,
        m: b.m,
        mu: 0,
        v: [b.vx, b.vy],
      });
    // The scene: 1,000 bodies with 10^6 recorded events (10^5 in --quick).
    const target = quick ? 100_000 : 1_000_000;
    const a = nowNs();
    tl.prolong({ events: target });
    const prolongNs = nowNs() - a;
    const events = tl.eventCount;
    const span = tl.horizon;
    const rnd = lcg(99);
    const lat = [];
    for (let i = 0; i < 200; i++) tl.stateAt(rnd() * span); // warm-up
    for (let i = 0; i < (quick ? 300 : 2000); i++) {
      const t = rnd() * span;
      const s = nowNs();
      tl.stateAt(t);
      lat.push(nowNs() - s);
    }
    lat.sort((x, y) => x - y);
    const historyBytes = tl.historyBytes();
    // Editing the past: a velocity given at a fraction of the horizon; the timeline recomputes from
    // the last keyframe before it (rebuilt from its motions) to the old horizon. Cost per recomputed
    // event should not depend on where the edit is; near the horizon (0.99) the restart dominates.
    const edits = [0.99, 0.9, 0.5].map((frac) => {
      const t = frac * span;
      const recomputed = tl.eventsBetween(t, span).length;
      const b = scene.bodies[0];
      const s = nowNs();
      tl.apply({ time: t, type: "giveVelocity", id: b.id, v: [b.vy, -b.vx] });
      const ns = nowNs() - s;
      return {
        fraction: frac,
        recomputedEvents: recomputed,
        ms: ns / 1e6,
        usPerRecomputedEvent: ns / 1e3 / recomputed,
      };
    });
    const res = {
      bodies: n,
      span,
      events,
      prolongEventsPerSecond: events / (prolongNs / 1e9),
      stateAtMedianUs: lat[Math.floor(lat.length / 2)] / 1e3,
      stateAtP95Us: lat[Math.floor(lat.length * 0.95)] / 1e3,
      stateAtMaxUs: lat[lat.length - 1] / 1e3,
      historyBytes,
      bytesPerEvent: historyBytes / Math.max(1, events),
      edits,
    };
    log(
      `  timeline: stateAt median ${res.stateAtMedianUs.toFixed(1)} µs, ${res.bytesPerEvent.toFixed(1)} B/event`,
    );
    return res;
  } catch (e) {
    log(`  timeline: ERROR ${e.message}`);
    return { error: String(e.message ?? e) };
  }
}

export async function runEngine(ctx) {
  if (typeof ctx.engine.World !== "function")
    return { error: "World is not exported by @chapgame/engine yet" };
  const out = {};
  out.scaling = await scaling(ctx);
  out.galperin7 = galperinRun(ctx, 7);
  out.reference = await againstReference(ctx);
  out.ablations = ablations(ctx);
  out.mixedRadii = mixedRadii(ctx);
  out.obstacles = obstacleRows(ctx);
  out.timeline = timeline(ctx);
  out.bulkReads = await bulkReads(ctx);
  out.instants = instants(ctx);
  return out;
}
