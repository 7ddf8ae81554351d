/**
 * Section "engine": chapgame alone.
 * - scaling: events/s of the dilute gas (10 % packing, speed 10) against N, per-event cost ratio
 *   N = 1e5 vs 1e3 (target ≤ 2) and events/s at N = 1e4 (target ≥ 1e6); heap bytes per body.
 *   Beside each row, the same gas run by minimalGas.mjs (the algorithm with every product feature
 *   stripped) and by its WebAssembly twin (bench/wasm): the ceilings JavaScript and WebAssembly reach
 *   here with this algorithm, timed the same way.
 * - galperin7: Galperin's billiard with 7 digits run to idle (target < 2 s, 3,141,592 collisions).
 * - reference: the fast engine against the tests' all-pairs reference simulator (reference.mjs).
 * - ablations (ablations.mjs): each World `optimizations` switch off in turn, on the scene where it should matter,
 *   same span, same events (checked), time ratio off/on.
 * - timeline: stateAt latency and history bytes per event, when the engine exports Timeline.
 */

import { lcg } from "../lib/lcg.mjs";
import { gc, median, nowNs, timedRuns } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { galperin } from "../scenes/galperin.mjs";
import { gas } from "../scenes/gas.mjs";
import { createMinimalGasWasm } from "../wasm/minimalGasWasm.mjs";
import { ablations } from "./ablations.mjs";
import { createMinimalGas } from "./minimalGas.mjs";
import { againstReference } from "./reference.mjs";

const collisions = (c) => c.bodyBody + c.bodyLine + c.bodyPoint;

/** Advance in chunks until `events` events or `seconds` of wall time, whichever comes first. */
function warmUp(world, events, seconds) {
  const a = nowNs();
  let done = 0;
  while (done < events && nowNs() - a < seconds * 1e9) done += world.advance({ maxEvents: 2000 }).events;
  return { events: done, ns: nowNs() - a };
}

const warmed = new Set();

/**
 * Memory per body of a prepared world (grid and event queue built): JS heap plus the typed arrays'
 * backing stores (outside the heap), grown over enough copies (at least 10^5 bodies in all) that
 * the collector's noise of a few hundred kB is small against it.
 */
function bytesPerBody(engine, scene) {
  const n = scene.bodies.length;
  const copies = Math.max(1, Math.ceil(1e5 / n));
  gc();
  const before = memoryInUse();
  const kept = [];
  for (let i = 0; i < copies; i++) {
    const world = buildWorld(engine, scene);
    world.advance({ maxEvents: 0 });
    kept.push(world);
  }
  gc();
  const bytes = memoryInUse() - before;
  return bytes / (kept.length * n);
}

/** Bytes in use by JS objects and by ArrayBuffer backing stores (typed arrays live outside the heap). */
function memoryInUse() {
  const m = process.memoryUsage();
  return m.heapUsed + m.arrayBuffers;
}

/** Events/s of a ceiling loop (`create(scene)` → { advance }): warm-up like the engine's, then `runs` batches. */
async function ceilingRate(create, scene, batch, runs) {
  if (!warmed.has(create)) {
    // Compile the loop once before any timing (the engine is warm from the sections before).
    const warm = await create(gas({ n: 1000, packing: 0.1, speed: 10, seed: 2, span: 1e9 }));
    warm.advance(300000);
    warmed.add(create);
  }
  gc();
  const loop = await create(scene);
  loop.advance(2 * scene.bodies.length);
  const t = timedRuns(
    () => {
      const a = nowNs();
      loop.advance(batch);
      return nowNs() - a;
    },
    { runs, budgetNs: 30e9 },
  );
  return { eventsPerSecond: batch / (t.medianNs / 1e9), nsPerEvent: t.medianNs / batch };
}

/** The WebAssembly ceiling, or its error (a failed compile must not cost the engine's numbers). */
async function wasmRate(scene, batch, runs) {
  try {
    return await ceilingRate(createMinimalGasWasm, scene, batch, runs);
  } catch (e) {
    return { error: String(e.message ?? e) };
  }
}

async function scaling({ quick, engine, log }) {
  const ns = quick ? [1000, 10000, 100000] : [1000, 3000, 10000, 30000, 100000];
  const target = quick ? 0.3 : 1.5; // seconds per timed batch
  const runs = quick ? 3 : 5;
  const rows = [];
  for (const n of ns) {
    try {
      const scene = gas({ n, packing: 0.1, speed: 10, seed: 11, span: 1e9 });
      const heapBytesPerBody = bytesPerBody(engine, scene);
      gc();
      const t0 = nowNs();
      const world = buildWorld(engine, scene);
      const buildNs = nowNs() - t0;
      // warm-up: leaves the grid start (about two events per disc) and measures the rate
      const w = warmUp(world, 2 * n, quick ? 1 : 4);
      const rate = w.events / (w.ns / 1e9);
      const batch = Math.max(5000, Math.min(2e6, Math.round((rate * target) / 1000) * 1000));
      const t = timedRuns(
        () => {
          const a = nowNs();
          const r = world.advance({ maxEvents: batch });
          if (r.events !== batch) throw new Error(`advance stopped after ${r.events} events (${r.reason})`);
          return nowNs() - a;
        },
        { runs, budgetNs: 30e9 },
      );
      const eventsPerSecond = batch / (t.medianNs / 1e9);
      const minimal = await ceilingRate(createMinimalGas, scene, batch, runs);
      const wasm = await wasmRate(scene, batch, runs);
      rows.push({
        n,
        batch,
        warmupEvents: w.events,
        runs: t.runs,
        eventsPerSecond,
        nsPerEvent: t.medianNs / batch,
        buildNs,
        heapBytesPerBody,
        simTime: world.time,
        minimalEventsPerSecond: minimal.eventsPerSecond,
        minimalNsPerEvent: minimal.nsPerEvent,
        wasmEventsPerSecond: wasm.eventsPerSecond ?? null,
        wasmNsPerEvent: wasm.nsPerEvent ?? null,
        wasmError: wasm.error ?? null,
      });
      log(
        `  scaling N=${n}: ${(eventsPerSecond / 1e6).toFixed(3)} M events/s (minimal loop: JS ${(minimal.eventsPerSecond / 1e6).toFixed(3)}, WebAssembly ${wasm.error ? `error: ${wasm.error}` : (wasm.eventsPerSecond / 1e6).toFixed(3)}), ${heapBytesPerBody.toFixed(0)} B/body`,
      );
    } catch (e) {
      rows.push({ n, error: String(e.message ?? e) });
      log(`  scaling N=${n}: ERROR ${e.message}`);
    }
  }
  const at = (n) => rows.find((r) => r.n === n && !r.error);
  const r3 = at(1000);
  const r5 = at(100000);
  const r4 = at(10000);
  return {
    rows,
    eventsPerSecondAt1e4: r4?.eventsPerSecond ?? null,
    costRatio1e5over1e3: r3 && r5 ? r5.nsPerEvent / r3.nsPerEvent : null,
    minimalEventsPerSecondAt1e4: r4?.minimalEventsPerSecond ?? null,
    minimalCostRatio1e5over1e3: r3 && r5 ? r5.minimalNsPerEvent / r3.minimalNsPerEvent : null,
    wasmEventsPerSecondAt1e4: r4?.wasmEventsPerSecond ?? null,
    wasmCostRatio1e5over1e3:
      r3?.wasmNsPerEvent && r5?.wasmNsPerEvent ? r5.wasmNsPerEvent / r3.wasmNsPerEvent : null,
    targets: { eventsPerSecondAt1e4: 1e6, costRatio: 2 },
  };
}

export function galperinRun({ quick, engine, log }, digits) {
  const scene = galperin(digits, { span: 1e9 });
  try {
    const once = () => {
      const world = buildWorld(engine, scene);
      const a = nowNs();
      world.advance({});
      const ns = nowNs() - a;
      return { ns, count: collisions(world.counts), world };
    };
    buildWorld(engine, galperin(5)).advance({}); // warm-up (JIT) on a smaller count
    const first = once();
    const t = quick
      ? { medianNs: first.ns, runs: 0 }
      : timedRuns(() => once().ns, { runs: 2, budgetNs: 20e9 });
    const all = quick ? [first.ns] : [first.ns, ...t.allNs];
    t.medianNs = median(all);
    const b = first.world.bodies();
    log(`  galperin ${digits}: ${first.count} collisions in ${(t.medianNs / 1e9).toFixed(3)} s`);
    return {
      digits,
      expected: scene.exact.collisions,
      count: first.count,
      correct: first.count === scene.exact.collisions,
      seconds: t.medianNs / 1e9,
      runs: all.length,
      final: b.map((s) => ({ id: s.id, vx: s.vx })),
    };
  } catch (e) {
    log(`  galperin ${digits}: ERROR ${e.message}`);
    return { digits, expected: scene.exact.collisions, error: String(e.message ?? e) };
  }
}

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
    // The issue's scene: 1,000 bodies with 10^6 recorded events (10^5 in --quick).
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
    // there to the old horizon. Cost per recomputed event should not depend on where the edit is.
    const edits = [0.9, 0.5].map((frac) => {
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
  out.timeline = timeline(ctx);
  return out;
}
