/**
 * The shape witness (shapeWitness.ts), in a child process that runs the built engine (dist/, built
 * first when older than the sources) with V8's test intrinsics (--allow-natives-syntax) and gc().
 * Both tests ask V8 directly (same map, optimised or not), which is deterministic: no timing.
 */
import { execFileSync } from "node:child_process";
import { join, resolve } from "node:path";
import { pathToFileURL } from "node:url";
import { beforeAll, expect, it } from "vitest";
import { buildEngineIfStale } from "../../test/builtEngine.js";

const pkg = resolve(import.meta.dirname, "../..");
const dist = pathToFileURL(join(pkg, "dist")).href;

beforeAll(() => buildEngineIfStale(join(pkg, "dist/sim/shapeWitness.js")));

/** Run `body` (an ES module's code; `engine`, `witness` and `gasWorld` in scope) and parse what it prints. */
function probe(body: string): unknown {
  const code = `
    const engine = await import("${dist}/index.js");
    const witness = (await import("${dist}/sim/shapeWitness.js")).shapeWitness();
    function gasWorld(seed) {
      const scene = engine.dilutedGas({ n: 300, packing: 0.1, seed });
      const w = new engine.World({ g: scene.g, gravity: scene.gravity });
      for (const { type, id, time, ...a } of scene.actions)
        if (type === "addLine") w.addLine(id, a.p1, a.p2, a.kind);
        else if (type === "addBody") w.addBody(id, { x: a.x, y: a.y, r: a.r, m: a.m, mu: a.mu, vx: a.v[0], vy: a.v[1] });
      return w;
    }
    ${body}`;
  const out = execFileSync(
    process.execPath,
    ["--allow-natives-syntax", "--expose-gc", "--input-type=module", "-e", code],
    { encoding: "utf8" },
  );
  return JSON.parse(out);
}

it("the witness's parts have the maps of Worlds that ran scenes of every kind", () => {
  // Parts compared before any of their own fields is read (a read would migrate a deprecated map):
  // the World, then its object fields, then theirs. Left out: arrays, typed arrays, functions and
  // Maps (V8's own maps, shared), and `tallyView`, one map per World by design (counts' read-only
  // view, read once per query, never by the simulation).
  const differing = probe(`
    for (const make of [engine.billiardsBreak, engine.newtonsCradle, engine.bouncingBalls, engine.brownian, () => engine.galperin(2)])
      engine.Timeline.fromScene(make()).prolong({ time: 3 });
    const live = gasWorld(7);
    live.advance({ untilTime: 3 });
    const differing = [];
    const skip = (v) => v === null || typeof v !== "object" || Array.isArray(v) || ArrayBuffer.isView(v) || v instanceof Map;
    let level = [["world", witness, live]];
    for (let depth = 0; depth < 3 && level.length > 0; depth++) {
      const next = [];
      for (const [path, a, b] of level) {
        if (!%HaveSameMap(a, b)) differing.push(path);
        for (const key of Object.keys(b)) {
          if (key === "tallyView" || skip(b[key])) continue;
          next.push([path + "." + key, a[key], b[key]]);
        }
      }
      level = next;
    }
    console.log(JSON.stringify(differing));
  `);
  expect(differing).toStrictEqual([]);
});

it("optimised code of the simulation survives a forced collection after the last World died", () => {
  // Methods whose optimised code checks the maps of a World, its body store, its grid and its
  // event queue, compiled on one World; that World then dies and a full collection runs.
  // Bit 4 of %GetOptimizationStatus: the function has optimised code (V8's OptimizationStatus).
  const result = probe(`
    const OPTIMIZED = 1 << 4;
    // In a function of its own, so that no register of this frame still holds the World afterwards.
    function optimizeOnOneWorld() {
      const world = gasWorld(3);
      world.advance({ untilTime: 0.5 });
      const calls = [
        [Object.getPrototypeOf(world.grid).column, world.grid, [1.5]],
        [Object.getPrototypeOf(Object.getPrototypeOf(world.heap)).peek, world.heap, []],
      ];
      for (let p = Object.getPrototypeOf(world); p !== Object.prototype; p = Object.getPrototypeOf(p))
        if (Object.hasOwn(p, "xAt")) calls.push([p.xAt, world, [0, world.time]]);
      for (const [f, self, args] of calls) {
        %PrepareFunctionForOptimization(f);
        f.apply(self, args);
        f.apply(self, args);
        %OptimizeFunctionOnNextCall(f);
        f.apply(self, args);
      }
      registry.register(world, "world");
      return calls.map(([f]) => f);
    }
    let died;
    const collected = new Promise((ok) => (died = ok));
    const registry = new FinalizationRegistry(() => died());
    const fns = optimizeOnOneWorld();
    const optimized = () => fns.map((f) => (%GetOptimizationStatus(f) & OPTIMIZED) !== 0);
    const before = optimized();
    globalThis.gc();
    await collected; // the World did die (the registry's callback ran after the collection)
    const after = optimized();
    console.log(JSON.stringify({ functions: fns.map((f) => f.name), before, after }));
  `);
  expect(result).toStrictEqual({
    functions: ["column", "peek", "xAt"],
    before: [true, true, true],
    after: [true, true, true],
  });
});
