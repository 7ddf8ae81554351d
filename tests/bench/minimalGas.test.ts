/**
 * The benchmark's ceiling loops (bench/engine/minimalGas.mjs and its WebAssembly twin) must simulate the same physics as the
 * engine, or its events/s mean nothing: energy is kept, discs never overlap or leave the box, and
 * after the same number of collisions the simulated time agrees with the engine's (the runs diverge
 * chaotically, so only statistically: the mean time between collisions is a property of the gas).
 * Their calendar queue must pop in exact (key, disc index) order: checked against a brute-force
 * minimum over every queued key at each pop.
 */
import { describe, expect, it } from "vitest";
import { createMinimalGas } from "../../bench/engine/minimalGas.mjs";
import { buildWorld } from "../../bench/peers/chapgame.mjs";
import { gas } from "../../bench/scenes/gas.mjs";
import { createMinimalGasWasm } from "../../bench/wasm/minimalGasWasm.mjs";
import * as engine from "../../packages/engine/src/index.js";

const scene = gas({ n: 400, packing: 0.1, speed: 10, seed: 5, span: 1e9 });
const EVENTS = 20000;

function energy(s: { vx: number; vy: number }[]): number {
  return s.reduce((e, b) => e + 0.5 * (b.vx * b.vx + b.vy * b.vy), 0);
}

describe("bench ceiling: minimalGas", () => {
  const loop = createMinimalGas(scene);
  const before = energy(loop.state());
  loop.advance(EVENTS);
  const after = loop.state();

  it("keeps kinetic energy (elastic, equal masses)", () => {
    expect(Math.abs(energy(after) - before) / before).toBeLessThan(1e-10);
  });

  it("never lets discs overlap or leave the box", () => {
    const { x0, y0, x1, y1 } = scene.box;
    for (let i = 0; i < after.length; i++) {
      const a = after[i] as { x: number; y: number };
      expect(a.x).toBeGreaterThanOrEqual(x0 + 1 - 1e-9);
      expect(a.x).toBeLessThanOrEqual(x1 - 1 + 1e-9);
      expect(a.y).toBeGreaterThanOrEqual(y0 + 1 - 1e-9);
      expect(a.y).toBeLessThanOrEqual(y1 - 1 + 1e-9);
      for (let j = i + 1; j < after.length; j++) {
        const b = after[j] as { x: number; y: number };
        expect(Math.hypot(a.x - b.x, a.y - b.y)).toBeGreaterThanOrEqual(2 * (1 - 1e-9));
      }
    }
  });

  it("reaches the same simulated time as the engine after the same number of collisions (within 5 %)", () => {
    const w = buildWorld(engine, scene);
    w.advance({ maxEvents: EVENTS });
    expect(Math.abs(loop.time() - w.time) / w.time).toBeLessThan(0.05);
  });

  it("its WebAssembly twin runs the same event sequence: the same time after as many collisions, bit for bit", async () => {
    const twin = await createMinimalGasWasm(scene);
    twin.advance(EVENTS);
    expect(Object.is(twin.time(), loop.time())).toBe(true);
  });

  it("pops every item in (key, disc index) order: each popped key is the minimum of all queued keys", () => {
    const small = gas({ n: 200, packing: 0.1, speed: 10, seed: 7, span: 1e9 });
    const popped: { disc: number; key: number; min: number; argmin: number }[] = [];
    const g: ReturnType<typeof createMinimalGas> = createMinimalGas(small, (disc, key) => {
      const keys = g.queueKeys();
      let argmin = 0;
      for (let i = 1; i < keys.length; i++) if ((keys[i] as number) < (keys[argmin] as number)) argmin = i;
      popped.push({ disc, key, min: keys[argmin] as number, argmin });
    });
    g.advance(2000);
    expect(popped.length).toBeGreaterThan(2000);
    const wrong = popped.filter((p) => p.key !== p.min || p.disc !== p.argmin);
    expect(wrong).toEqual([]);
    // The run went through the adaptive path (at least one rebuild of the bucket width).
    expect(g.queueStats().rebuilds).toBeGreaterThan(0);
  });
});
