/**
 * Engine section, scaling rows: events/s of the dilute gas (10 % packing, speed 10) against N, the
 * per-event cost ratio N = 1e5 vs 1e3 (target ≤ 2) and events/s at N = 1e4 (target ≥ 1e6); memory
 * per body, and bytes of heap allocated per event. Beside each row, the same gas run by minimalGas.mjs (the algorithm with every product
 * feature stripped) and by its WebAssembly twin (bench/wasm): the ceilings JavaScript and
 * WebAssembly reach here with this algorithm, timed the same way.
 *
 * Each N is measured in its own Node processes (three in full runs, in rounds of one process per N,
 * the median kept; `node
 * --expose-gc scaling.mjs <n> <quick>` prints one process's row as one JSON line), so that no row
 * inherits the JIT's state from other rows or sections, as a program simulating one gas would.
 * Each process first compiles the engine and both loops on a 1,000-disc gas, then times batches
 * after a warm-up that leaves the grid start. The JavaScript loop is timed twice: first as the only
 * instance in its process, compiled on the measured gas (V8 then specialises its code to that one
 * instance: the best plain JavaScript does here), then again after the small gas's instance (code shared by
 * instances, as the engine's class-based code always is), each warmed on the measured gas alike.
 */
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { allocatedBytes } from "../lib/allocation.mjs";
import { loadEngine } from "../lib/engine.mjs";
import { gc, nowNs, timedRuns } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { gas } from "../scenes/gas.mjs";
import { createMinimalGasWasm } from "../wasm/minimalGasWasm.mjs";
import { createMinimalGas } from "./minimalGas.mjs";

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
async function bytesPerBody(engine, scene) {
  const n = scene.bodies.length;
  const copies = Math.max(1, Math.ceil(1e5 / n));
  await settle();
  const before = memoryInUse();
  const kept = [];
  for (let i = 0; i < copies; i++) {
    const world = buildWorld(engine, scene);
    world.advance({ maxEvents: 0 });
    kept.push(world);
  }
  await settle();
  const bytes = memoryInUse() - before;
  return bytes / (kept.length * n);
}

/**
 * Collect, and let the event loop turn, three times: right after gc() the array buffers it freed
 * are at times still counted (up to 190 B/body more at N = 1e5; docs/engine-throughput.md, session 26).
 */
async function settle() {
  for (let i = 0; i < 3; i++) {
    gc();
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
}

/** Bytes in use by JS objects and by ArrayBuffer backing stores (typed arrays live outside the heap). */
function memoryInUse() {
  const m = process.memoryUsage();
  return m.heapUsed + m.arrayBuffers;
}

/** Events/s of a ceiling loop (`create(scene)` → { advance }): warm-up like the engine's, then `runs` batches. */
async function ceilingRate(create, scene, batch, runs, warmEvents = 0) {
  if (!warmed.has(create)) {
    // Compile the loop once before any timing (as the engine is, in measureRow).
    const warm = await create(gas({ n: 1000, packing: 0.1, speed: 10, seed: 2, span: 1e9 }));
    warm.advance(300000);
    warmed.add(create);
  }
  gc();
  return loopRate(await create(scene), scene.bodies.length, batch, runs, warmEvents);
}

/** Events/s of a ceiling loop of n discs: 2n events and `warmEvents` more, then `runs` timed batches. */
function loopRate(loop, n, batch, runs, warmEvents) {
  loop.advance(2 * n);
  if (warmEvents > 0) loop.advance(warmEvents);
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

/**
 * Events/s of a ceiling loop that is the only instance of its kind in this process, compiled on the
 * measured gas itself (warmed by `warmEvents` events). V8 specialises a closure's optimised code to
 * its one instance (its typed arrays and sizes become constants: "function context
 * specialisation"); a second instance, such as ceilingRate's warm-up, loses that for both. Run it
 * before ceilingRate in a process.
 */
function oneInstanceRate(create, scene, batch, runs, warmEvents) {
  gc();
  return loopRate(create(scene), scene.bodies.length, batch, runs, warmEvents);
}

/** The WebAssembly ceiling, or its error (a failed compile must not cost the engine's numbers). */
async function wasmRate(scene, batch, runs) {
  try {
    return await ceilingRate(createMinimalGasWasm, scene, batch, runs);
  } catch (e) {
    return { error: String(e.message ?? e) };
  }
}

/** One row, measured in this process. */
async function measureRow(engine, n, quick) {
  const target = quick ? 0.3 : 1.5; // seconds per timed batch
  const runs = quick ? 3 : 5;
  // Compile the engine before any timing, on a small gas (as ceilingRate does for the loops).
  const warm = buildWorld(engine, gas({ n: 1000, packing: 0.1, speed: 10, seed: 2, span: 1e9 }));
  warm.advance({ maxEvents: quick ? 100000 : 300000 });
  const scene = gas({ n, packing: 0.1, speed: 10, seed: 11, span: 1e9 });
  const heapBytesPerBody = await bytesPerBody(engine, scene);
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
  // Heap allocation per event, after the timed batches (the sampling profiler slows what it watches).
  let allocEvents = 0;
  const allocated = await allocatedBytes(() => {
    allocEvents = world.advance({ maxEvents: Math.min(batch, 100000) }).events;
  });
  // Both JavaScript timings start from the same stage of the gas: 2N events, then the warm-up.
  const warmEvents = quick ? 100000 : 300000;
  const minimalOne = oneInstanceRate(createMinimalGas, scene, batch, runs, warmEvents);
  const minimal = await ceilingRate(createMinimalGas, scene, batch, runs, warmEvents);
  const wasm = await wasmRate(scene, batch, runs);
  const row = {
    n,
    batch,
    warmupEvents: w.events,
    runs: t.runs,
    eventsPerSecond,
    nsPerEvent: t.medianNs / batch,
    buildNs,
    heapBytesPerBody,
    allocatedBytesPerEvent: allocEvents > 0 ? allocated / allocEvents : null,
    simTime: world.time,
    minimalEventsPerSecond: minimal.eventsPerSecond,
    minimalNsPerEvent: minimal.nsPerEvent,
    minimalOneInstanceEventsPerSecond: minimalOne.eventsPerSecond,
    minimalOneInstanceNsPerEvent: minimalOne.nsPerEvent,
    wasmEventsPerSecond: wasm.eventsPerSecond ?? null,
    wasmNsPerEvent: wasm.nsPerEvent ?? null,
    wasmError: wasm.error ?? null,
  };
  return row;
}

/** One child process measuring row n. */
function rowInChild(n, quick) {
  const out = execFileSync(
    process.execPath,
    ["--expose-gc", fileURLToPath(import.meta.url), String(n), quick ? "1" : "0"],
    { encoding: "utf8", maxBuffer: 1 << 20 },
  );
  return JSON.parse(out.trim().split("\n").pop());
}

/** Median of the numbers among xs (null when there are none). */
function medianOf(xs) {
  const v = xs.filter((x) => typeof x === "number").sort((a, b) => a - b);
  return v.length === 0
    ? null
    : v.length % 2
      ? v[v.length >> 1]
      : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
}

/**
 * Row n from its child processes' rows: each rate is the median over the processes (at 10^5
 * discs the rate of one process varies by up to 30 % from one process to the next, with memory
 * placement; the batches within a process do not show it).
 */
function row(n, all) {
  const pick = (k) => medianOf(all.map((r) => r[k]));
  const first = all[0];
  return {
    ...first,
    n,
    processes: all.length,
    eventsPerSecondPerProcess: all.map((r) => r.eventsPerSecond),
    eventsPerSecond: pick("eventsPerSecond"),
    nsPerEvent: pick("nsPerEvent"),
    heapBytesPerBody: pick("heapBytesPerBody"),
    allocatedBytesPerEvent: pick("allocatedBytesPerEvent"),
    minimalEventsPerSecond: pick("minimalEventsPerSecond"),
    minimalNsPerEvent: pick("minimalNsPerEvent"),
    minimalOneInstanceEventsPerSecond: pick("minimalOneInstanceEventsPerSecond"),
    minimalOneInstanceNsPerEvent: pick("minimalOneInstanceNsPerEvent"),
    wasmEventsPerSecond: pick("wasmEventsPerSecond"),
    wasmNsPerEvent: pick("wasmNsPerEvent"),
  };
}

export async function scaling({ quick, log }) {
  const ns = quick ? [1000, 10000, 100000] : [1000, 3000, 10000, 30000, 100000];
  const processes = quick ? 1 : 3;
  // The processes run in rounds, each round one process per N from small to large: a drift of the
  // machine's speed during the section then falls on every N alike, not on the last N measured
  // (when each N ran its processes back to back, N = 10^5 came last and took all of a late drift).
  const perN = new Map(ns.map((n) => [n, []]));
  const errors = new Map();
  for (let round = 0; round < processes; round++) {
    for (const n of ns) {
      if (errors.has(n)) continue;
      try {
        perN.get(n).push(rowInChild(n, quick));
      } catch (e) {
        errors.set(n, String(e.stderr || e.message || e).slice(0, 2000));
        log(`  scaling N=${n}: ERROR ${String(e.stderr || e.message).slice(0, 500)}`);
      }
    }
  }
  const rows = ns.map((n) => {
    if (errors.has(n)) return { n, error: errors.get(n) };
    const r = row(n, perN.get(n));
    log(
      `  scaling N=${n}: ${(r.eventsPerSecond / 1e6).toFixed(3)} M events/s (minimal loop: JS ${(r.minimalEventsPerSecond / 1e6).toFixed(3)}, JS one instance ${(r.minimalOneInstanceEventsPerSecond / 1e6).toFixed(3)}, WebAssembly ${r.wasmError ? `error: ${r.wasmError}` : (r.wasmEventsPerSecond / 1e6).toFixed(3)}), ${r.heapBytesPerBody.toFixed(0)} B/body${processes > 1 ? ` (median of ${processes} processes, one per round: ${r.eventsPerSecondPerProcess.map((x) => (x / 1e6).toFixed(3)).join(", ")})` : ""}`,
    );
    return r;
  });
  const at = (n) => rows.find((r) => r.n === n && !r.error);
  const r3 = at(1000);
  const r5 = at(100000);
  const r4 = at(10000);
  return {
    rows,
    processesPerN: processes,
    eventsPerSecondAt1e4: r4?.eventsPerSecond ?? null,
    costRatio1e5over1e3: r3 && r5 ? r5.nsPerEvent / r3.nsPerEvent : null,
    minimalEventsPerSecondAt1e4: r4?.minimalEventsPerSecond ?? null,
    minimalCostRatio1e5over1e3: r3 && r5 ? r5.minimalNsPerEvent / r3.minimalNsPerEvent : null,
    minimalOneInstanceEventsPerSecondAt1e4: r4?.minimalOneInstanceEventsPerSecond ?? null,
    minimalOneInstanceCostRatio1e5over1e3:
      r3?.minimalOneInstanceNsPerEvent && r5?.minimalOneInstanceNsPerEvent
        ? r5.minimalOneInstanceNsPerEvent / r3.minimalOneInstanceNsPerEvent
        : null,
    wasmEventsPerSecondAt1e4: r4?.wasmEventsPerSecond ?? null,
    wasmCostRatio1e5over1e3:
      r3?.wasmNsPerEvent && r5?.wasmNsPerEvent ? r5.wasmNsPerEvent / r3.wasmNsPerEvent : null,
    targets: { eventsPerSecondAt1e4: 1e6, costRatio: 2 },
  };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { engine } = await loadEngine();
  const row = await measureRow(engine, Number(process.argv[2]), process.argv[3] === "1");
  process.stdout.write(`${JSON.stringify(row)}\n`);
}
