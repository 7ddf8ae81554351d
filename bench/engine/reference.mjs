/**
 * The fast engine against the all-pairs reference simulator of the engine's tests
 * (packages/engine/test/referenceWorld.ts: every pair recomputed after every event, the seed's
 * method; its contact times in referenceTimes.ts). Those files are TypeScript test support, not
 * part of the built package, so they and the engine sources they import are transpiled
 * (typescript's transpileModule, no type check) into the ignored bench/results/tmp/reference/.
 * Same gas, same number of events; the event sequences are compared too (kind, participants, time
 * to 1e-12 relative).
 */
import { mkdirSync, readdirSync, readFileSync, statSync, writeFileSync } from "node:fs";
import { dirname, join, relative } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import ts from "typescript";
import { nowNs } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { gas } from "../scenes/gas.mjs";

const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
const ENGINE = join(ROOT, "packages", "engine");
const OUT = join(ROOT, "bench", "results", "tmp", "reference");

function walk(dir, files = []) {
  for (const f of readdirSync(dir)) {
    const p = join(dir, f);
    if (statSync(p).isDirectory()) walk(p, files);
    else if (f.endsWith(".ts") && !f.endsWith(".test.ts") && !f.endsWith(".d.ts")) files.push(p);
  }
  return files;
}

async function loadReference() {
  const files = [
    ...walk(join(ENGINE, "src")),
    join(ENGINE, "test", "referenceWorld.ts"),
    join(ENGINE, "test", "referenceTimes.ts"),
  ];
  for (const f of files) {
    const js = ts.transpileModule(readFileSync(f, "utf8"), {
      compilerOptions: { module: ts.ModuleKind.ESNext, target: ts.ScriptTarget.ES2022 },
    }).outputText;
    const out = join(OUT, relative(ENGINE, f)).replace(/\.ts$/, ".js");
    mkdirSync(dirname(out), { recursive: true });
    writeFileSync(out, js);
  }
  writeFileSync(join(OUT, "package.json"), '{ "type": "module" }\n');
  return (await import(pathToFileURL(join(OUT, "test", "referenceWorld.js")).href)).ReferenceWorld;
}

function toSpec(scene) {
  return {
    g: scene.g,
    gravity: scene.gravity,
    bodies: scene.bodies.map(({ id, x, y, vx, vy, r, m, mu }) => ({ id, x, y, vx, vy, r, m, mu })),
    lines: scene.walls.map((w) => ({ id: w.id, p1: w.p1, p2: w.p2, kind: w.kind })),
    points: [],
  };
}

export async function againstReference({ quick, engine, log }) {
  let ReferenceWorld;
  try {
    ReferenceWorld = await loadReference();
  } catch (e) {
    return { error: `could not load the reference simulator: ${e.message}` };
  }
  const sizes = quick
    ? [
        [100, 1000],
        [300, 200],
      ]
    : [
        [100, 5000],
        [300, 2000],
        [1000, 300],
      ];
  const rows = [];
  for (const [n, events] of sizes) {
    try {
      const scene = gas({ n, packing: 0.1, speed: 10, seed: 17, span: 1e9 });
      const ref = new ReferenceWorld(toSpec(scene));
      const a = nowNs();
      const refEvents = ref.run(events);
      const refNs = nowNs() - a;
      const world = buildWorld(engine, scene);
      const fast = [];
      const b = nowNs();
      world.advance({ maxEvents: events }, (e) => {
        fast.push({ time: e.time, kind: e.kind, a: e.a, b: e.b });
      });
      const fastNs = nowNs() - b;
      let same = fast.length === refEvents.length;
      let firstDiff = null;
      for (let i = 0; same && i < fast.length; i++) {
        const p = fast[i];
        const q = refEvents[i];
        const ids = (x) => [x.a, x.b].sort().join("+");
        if (
          p.kind !== q.kind ||
          ids(p) !== ids(q) ||
          Math.abs(p.time - q.time) > 1e-12 * Math.max(1, Math.abs(q.time))
        ) {
          same = false;
          firstDiff = i;
        }
      }
      rows.push({
        n,
        events,
        refEventsPerSecond: events / (refNs / 1e9),
        fastEventsPerSecond: events / (fastNs / 1e9),
        speedup: refNs / fastNs,
        sameSequence: same,
        firstDiff,
      });
      log(`  reference N=${n}: fast ×${(refNs / fastNs).toFixed(1)}, same sequence ${same}`);
    } catch (e) {
      rows.push({ n, events, error: String(e.message ?? e) });
      log(`  reference N=${n}: ERROR ${e.message}`);
    }
  }
  return { rows };
}
