/**
 * Section "stress": the numerical stress scenes at benchmark size. For each: events, time, worst
 * overlap sampled at many instants (relative to the contact distance), contact-distance error at
 * body–body events, energy error, escaped bodies. Plus far approaches (far.mjs), the long run (energy drift against event
 * count) and Galperin's billiard pushed digit by digit until the count is wrong or the run fails.
 */

import { nowNs } from "../lib/timing.mjs";
import { buildWorld, read as readAll } from "../peers/chapgame.mjs";
import { emptyState, escaped, kineticEnergy, worstOverlap } from "../peers/metrics.mjs";
import { galperin } from "../scenes/galperin.mjs";
import { gas } from "../scenes/gas.mjs";
import { grazing, highSpeed, largeOffset, massRatio, nearSimultaneous, roundOffContacts } from "./cases.mjs";
import { runFarApproaches } from "./far.mjs";

function stressCase(engine, scene, samples) {
  const world = buildWorld(engine, scene);
  const s = emptyState(scene.bodies.length);
  const radius = new Map(scene.bodies.map((b) => [b.id, b.r]));
  const ke0 = kineticEnergy(scene, readAll(world, scene, s));
  let contactError = 0;
  const onEvent = (e) => {
    if (e.kind !== "bodyBody" || e.b === null) return;
    const a = world.body(e.a, e.time);
    const b = world.body(e.b, e.time);
    const R = radius.get(e.a) + radius.get(e.b);
    contactError = Math.max(contactError, Math.abs(Math.hypot(a.x - b.x, a.y - b.y) - R) / R);
  };
  let worst = 0;
  let esc = 0;
  let events = 0;
  let ns = 0;
  for (let k = 1; k <= samples; k++) {
    const a = nowNs();
    events += world.advance({ untilTime: (scene.span * k) / samples }, onEvent).events;
    ns += nowNs() - a;
    readAll(world, scene, s);
    worst = Math.max(worst, worstOverlap(scene, s));
    esc = Math.max(esc, escaped(scene, s));
  }
  const ke1 = kineticEnergy(scene, s);
  return {
    id: scene.id,
    bodies: scene.bodies.length,
    span: scene.span,
    events,
    ms: ns / 1e6,
    worstOverlap: worst,
    tolerance: scene.tolerance,
    overlapOk: worst <= scene.tolerance,
    contactError,
    energyError: ke0 > 0 ? (ke1 - ke0) / ke0 : null,
    escaped: esc,
  };
}

function longRun(engine, total, maxSeconds, log) {
  const scene = gas({ n: 1000, packing: 0.1, speed: 10, seed: 21, span: 1e12 });
  const world = buildWorld(engine, scene);
  const s = emptyState(scene.bodies.length);
  const ke0 = kineticEnergy(scene, readAll(world, scene, s));
  const series = [];
  let done = 0;
  const a = nowNs();
  while (done < total && nowNs() - a < maxSeconds * 1e9) {
    // checkpoints about 12 % apart, so the drift is sampled evenly on a log axis
    const step = Math.min(total - done, Math.max(1000, Math.round(done * 0.12)));
    const r = world.advance({ maxEvents: step });
    done += r.events;
    const ke = kineticEnergy(scene, readAll(world, scene, s));
    series.push([done, (ke - ke0) / ke0]);
    if (r.reason !== "events") break;
  }
  const seconds = (nowNs() - a) / 1e9;
  const worst = Math.max(...series.map(([, e]) => Math.abs(e)));
  log(`  long run: ${done} events in ${seconds.toFixed(1)} s, worst |ΔE/E| ${worst.toExponential(2)}`);
  return {
    bodies: 1000,
    target: total,
    maxSeconds,
    events: done,
    seconds,
    worstDrift: worst,
    finalDrift: series.at(-1)?.[1] ?? null,
    series,
  };
}

export function galperinPush(engine, { maxDigits, budgetSeconds, log }) {
  const rows = [];
  let lastSeconds = 0;
  for (let d = 1; d <= maxDigits; d++) {
    const estimate = lastSeconds * 10;
    if (d > 7 && estimate > budgetSeconds && Number.isFinite(budgetSeconds)) {
      rows.push({
        digits: d,
        skipped: `estimated ${estimate.toFixed(0)} s (10× the previous digit) exceeds the ${budgetSeconds} s budget`,
      });
      log(`  galperin push ${d}: skipped (estimated ${estimate.toFixed(0)} s)`);
      break;
    }
    const scene = galperin(d, { span: 1e9 });
    const expected = scene.exact.collisions;
    let prev = Number.NEGATIVE_INFINITY;
    let minGap = Number.POSITIVE_INFINITY;
    let sameTime = 0;
    let lastTime = 0;
    let minGapAt = 0;
    const onEvent = (e) => {
      if (e.time === prev) sameTime++;
      else if (prev > Number.NEGATIVE_INFINITY && e.time - prev < minGap) {
        minGap = e.time - prev;
        minGapAt = e.time;
      }
      prev = e.time;
      lastTime = e.time;
    };
    const world = buildWorld(engine, scene);
    const a = nowNs();
    let error = null;
    try {
      world.advance({}, onEvent);
    } catch (e) {
      error = String(e.message ?? e);
    }
    lastSeconds = (nowNs() - a) / 1e9;
    const c = world.counts;
    const count = c.bodyBody + c.bodyLine + c.bodyPoint;
    const row = {
      digits: d,
      expected,
      count,
      correct: !error && count === expected,
      seconds: lastSeconds,
      minGap,
      minGapAt,
      sameTime,
      lastTime,
      error,
    };
    rows.push(row);
    log(
      `  galperin push ${d}: ${count} / ${expected}${error ? ` (${error})` : ""} in ${lastSeconds.toFixed(2)} s`,
    );
    if (!row.correct) break;
  }
  const firstWrong = rows.find((r) => r.correct === false)?.digits ?? null;
  return { rows, firstWrong, lastCorrect: rows.filter((r) => r.correct).at(-1)?.digits ?? 0 };
}

export function runStress({ quick, engine, log }) {
  if (typeof engine.World !== "function") return { error: "World is not exported by @chapgame/engine yet" };
  const samples = quick ? 200 : 1000;
  const scenes = [
    grazing(34),
    nearSimultaneous(10),
    roundOffContacts(quick ? 4 : 10, 24),
    largeOffset(quick ? 200 : 1000),
    ...[1e3, 1e6, 1e9, 1e12].map((r) => massRatio(r)),
    ...[1e2, 1e4, 1e6].map((v) => highSpeed(v)),
  ];
  const cases = scenes.map((scene) => {
    try {
      const r = stressCase(engine, scene, samples);
      log(
        `  stress ${scene.id}: ${r.events} events, overlap ${r.worstOverlap.toExponential(2)}, ΔE/E ${r.energyError?.toExponential(2)}`,
      );
      return r;
    } catch (e) {
      log(`  stress ${scene.id}: ERROR ${e.message}`);
      return { id: scene.id, bodies: scene.bodies.length, error: String(e.message ?? e) };
    }
  });
  let long;
  try {
    long = longRun(engine, quick ? 2e5 : 1e7, quick ? 10 : 150, log);
  } catch (e) {
    long = { error: String(e.message ?? e) };
  }
  let far;
  try {
    far = runFarApproaches(engine, log);
  } catch (e) {
    far = { error: String(e.message ?? e) };
  }
  const push = galperinPush(engine, { maxDigits: quick ? 6 : 10, budgetSeconds: quick ? 5 : 240, log });
  return { samples, cases, farApproaches: far, longRun: long, galperinPush: push };
}
