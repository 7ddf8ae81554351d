/**
 * Engine section, Galperin's billiard at 7 digits (issue 2: 3,141,592 collisions, exact, in under
 * GALPERIN7_TARGET_SECONDS): run to idle in fresh Node processes (three in full runs, one in quick
 * runs), each warmed up on 5 digits and then timed once; the median is kept and every process's
 * time is in the JSON. A fresh process measures what a program simulating this billiard sees: in
 * the benchmark's main process, after the peers section has run the World on other scenes, the same
 * run took 2.30–2.32 s in two full runs on 22 Nov, when it took 1.82–2.07 s alone.
 *
 * `node --expose-gc galperin7.mjs <digits>` prints one process's result as a JSON line.
 */
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { loadEngine } from "../lib/engine.mjs";
import { median, nowNs } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { galperin } from "../scenes/galperin.mjs";

/** Issue 2's target for Galperin's billiard at 7 digits: the exact count in under this many seconds. */
export const GALPERIN7_TARGET_SECONDS = 2;

const collisions = (c) => c.bodyBody + c.bodyLine + c.bodyPoint;

/** One process: warm up on 5 digits, then run `digits` to idle once, timed. */
function measureHere(engine, digits) {
  buildWorld(engine, galperin(5)).advance({});
  const world = buildWorld(engine, galperin(digits, { span: 1e9 }));
  const a = nowNs();
  world.advance({});
  const ns = nowNs() - a;
  return {
    count: collisions(world.counts),
    seconds: ns / 1e9,
    final: world.bodies().map((s) => ({ id: s.id, vx: s.vx })),
  };
}

function measureInChild(digits) {
  const out = execFileSync(
    process.execPath,
    ["--expose-gc", fileURLToPath(import.meta.url), String(digits)],
    {
      encoding: "utf8",
      maxBuffer: 1 << 20,
    },
  );
  return JSON.parse(out.trim().split("\n").pop());
}

export function galperinRun({ quick, log }, digits) {
  const scene = galperin(digits, { span: 1e9 });
  const expected = scene.exact.collisions;
  try {
    const processes = quick ? 1 : 3;
    const runs = [];
    for (let i = 0; i < processes; i++) runs.push(measureInChild(digits));
    const seconds = median(runs.map((r) => r.seconds));
    const counts = runs.map((r) => r.count);
    log(
      `  galperin ${digits}: ${counts[0]} collisions in ${seconds.toFixed(3)} s (median of ${processes} processes: ${runs.map((r) => r.seconds.toFixed(3)).join(", ")})`,
    );
    return {
      digits,
      expected,
      count: counts[0],
      correct: counts.every((c) => c === expected),
      seconds,
      targetSeconds: GALPERIN7_TARGET_SECONDS,
      runs: processes,
      processes,
      secondsPerProcess: runs.map((r) => r.seconds),
      final: runs[0].final,
    };
  } catch (e) {
    log(`  galperin ${digits}: ERROR ${e.message}`);
    return { digits, expected, error: String(e.message ?? e) };
  }
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { engine } = await loadEngine();
  process.stdout.write(`${JSON.stringify(measureHere(engine, Number(process.argv[2])))}\n`);
}
