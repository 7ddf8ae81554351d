/**
 * Engine section, bulk reads: nanoseconds per read of all 20,000 bodies of a 10 % gas, as objects
 * (Timeline.stateAt, World.bodies) and as arrays written into the previous result
 * (Timeline.bodyArraysAt(t, into), World.bodyArrays(t, into)), and the bytes of JS heap each read
 * allocates (bench/lib/allocation.mjs: typed arrays' stores are outside the heap; the timeline's
 * read one step of the playback on). The timeline's reads go over the same times forwards
 * (playback: bodyArraysAt goes on from its last replay) and backwards (every read replays from the
 * keyframe, as stateAt always does); the World's at its current time. Passes of the two ways
 * alternate; each row is the median of the passes' means.
 * About 8 s (3 s with --quick). `node bench/engine/bulkReads.mjs [--quick]` runs it alone.
 */
import { fileURLToPath } from "node:url";
import { allocatedBytes } from "../lib/allocation.mjs";
import { loadEngine } from "../lib/engine.mjs";
import { gc, median, nowNs } from "../lib/timing.mjs";
import { gas } from "../scenes/gas.mjs";

const BODIES = 20000;

/** The gas as a scene file (the bodies and walls added by actions at t = 0). */
function gasScene(n) {
  const s = gas({ n, packing: 0.1, speed: 10, seed: 3, span: 1 });
  const actions = s.walls.map((w) => ({
    time: 0,
    type: "addLine",
    id: w.id,
    p1: w.p1,
    p2: w.p2,
    kind: w.kind,
  }));
  for (const b of s.bodies)
    actions.push({
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
  return { scene: { format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions }, gas: s };
}

/** Median over `passes` of the mean ns per call of each way's `read(t)` over `times`, alternating. */
function compare(ways, times, passes) {
  const perPass = ways.map(() => []);
  for (let p = -1; p < passes; p++) {
    ways.forEach((w, k) => {
      gc();
      const a = nowNs();
      for (const t of times) w.read(t);
      if (p >= 0) perPass[k].push((nowNs() - a) / times.length); // pass -1 warms up
    });
  }
  return perPass.map((v) => median(v));
}

export async function bulkReads({ quick, engine, log }) {
  if (typeof engine.Timeline?.prototype?.bodyArraysAt !== "function")
    return { error: "Timeline.bodyArraysAt is not in this engine" };
  try {
    return await measure({ quick, engine, log });
  } catch (e) {
    log(`  bulk reads: ERROR ${e.message}`);
    return { error: String(e.message ?? e) };
  }
}

async function measure({ quick, engine, log }) {
  const n = BODIES;
  const { scene, gas: g } = gasScene(n);
  const tl = engine.Timeline.fromScene(scene, { compute: false });
  tl.prolong({ events: (quick ? 1 : 2) * n });
  const h = tl.horizon;
  const reads = quick ? 12 : 30;
  const passes = quick ? 2 : 3;
  const forwards = Array.from({ length: reads }, (_, k) => (h * k) / (reads - 1));
  const backwards = [...forwards].reverse();
  let into;
  const timeline = [
    { name: "stateAt(t)", read: (t) => tl.stateAt(t) },
    { name: "bodyArraysAt(t, into)", read: (t) => (into = tl.bodyArraysAt(t, into)) },
  ];
  const rows = [];
  for (const [order, times] of [
    ["forwards", forwards],
    ["backwards", backwards],
  ]) {
    const [objects, arrays] = compare(timeline, times, passes);
    rows.push({ api: "Timeline", order, objectsNs: objects, arraysNs: arrays });
  }
  const world = new engine.World({ g: 0 });
  for (const w of g.walls) world.addLine(w.id, w.p1, w.p2, w.kind);
  for (const b of g.bodies) world.addBody(b.id, { x: b.x, y: b.y, r: b.r, m: b.m, vx: b.vx, vy: b.vy });
  world.advance({ maxEvents: n });
  let wInto;
  const now = Array.from({ length: reads }, () => world.time);
  const [objects, arrays] = compare(
    [
      { name: "bodies(t)", read: (t) => world.bodies(t) },
      { name: "bodyArrays(t, into)", read: (t) => (wInto = world.bodyArrays(t, wInto)) },
    ],
    now,
    passes,
  );
  rows.push({ api: "World", order: "now", objectsNs: objects, arraysNs: arrays });
  // heap bytes of one read each, `into` made already: the timeline's one step of the playback on
  const k = Math.floor(reads / 2);
  for (let j = 0; j <= k; j++) tl.bodyArraysAt(forwards[j], into);
  const allocation = {
    stateAt: await allocatedBytes(() => tl.stateAt(forwards[k + 1])),
    bodyArraysAt: await allocatedBytes(() => tl.bodyArraysAt(forwards[k + 1], into)),
    bodies: await allocatedBytes(() => world.bodies()),
    bodyArrays: await allocatedBytes(() => world.bodyArrays(world.time, wInto)),
  };
  for (const r of rows)
    log(
      `  bulk reads, ${r.api} ${r.order}: ${(r.objectsNs / 1e6).toFixed(2)} ms as objects, ${(r.arraysNs / 1e6).toFixed(2)} ms as arrays`,
    );
  return { bodies: n, events: tl.eventCount, horizon: h, reads, passes, rows, allocation };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { engine } = await loadEngine();
  const quick = process.argv.includes("--quick");
  const out = await bulkReads({ quick, engine, log: (m) => console.error(m) });
  process.stdout.write(`${JSON.stringify(out, null, 1)}\n`);
}
