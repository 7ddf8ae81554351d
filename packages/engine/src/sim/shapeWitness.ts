/**
 * The shape witness: one small World, built and run once when the engine loads and kept for the
 * process's lifetime, so that the hidden classes (V8 "maps") of a World and of its parts (body
 * store, grid, event queue, event record, ...) never die. No result depends on it: it only keeps
 * V8's optimised code of the simulation alive after the last World was collected.
 *
 * Why (docs/engine-throughput.md, session 29): optimised code holds the maps it checks weakly. An
 * ordinary full collection keeps a map whose objects all died (V8 retains it while its
 * constructor lives), but a forced one (`gc()`), and by V8's rule any that reduces memory (its
 * memory reducer, a low-memory notification), drops it, and with it every optimised function that
 * checked it: the next World ran its first events 10 to 20 times slower, as unoptimised code, until
 * V8 compiled the simulation again. A live object of each map keeps the maps, hence the code.
 *
 * The witness must hold the maps the Worlds in use have, not older ones: a field that first held a
 * small integer and later a fraction gets a new map (the old one is deprecated, and a witness that
 * still had it would keep only that one). So the witness is built with fractional options, and its
 * run below stores fractions in every number field a simulation writes (times, positions, the
 * grid's origin and cell size, the event queue's bucket width, the event record), before it is
 * kept. shapeWitness.test.ts checks that after Worlds of several kinds ran, the witness's parts
 * still have the same maps as theirs.
 */
import type { WorldOptions } from "./types.js";
import type { World } from "./world.js";

/** Options of the witness: fractions, so that the number fields they set are stored as doubles. */
export const WITNESS_OPTIONS: WorldOptions = { g: 0.5, gravity: [0.5, 0.25], time: 0.5 };

/** Discs of the witness's scene: enough for a grid of several cells (12 gave one) and a sized event queue. */
const WITNESS_DISCS = 40;

/** Worlds kept alive for the process's lifetime (one: the witness). */
const kept: World[] = [];

/**
 * Run `world` (a new World made with WITNESS_OPTIONS) through a small scene and keep it: discs
 * under a sideways gravity collide and meet a segment; a point and a ray stand aside.
 */
export function keepAsShapeWitness(world: World): void {
  world.addLine("wall", [6.5, -20.5], [6.5, 20.5], "segment");
  world.addLine("ray", [-30.5, -30.5], [-40.5, -30.5], "ray");
  world.addPoint("pin", [-20.5, 10.5]);
  for (let i = 0; i < WITNESS_DISCS; i++) {
    const x = 0.5 + 2.25 * (i % 4);
    const y = 0.75 + 2.5 * Math.floor(i / 4);
    world.addBody(`d${i}`, { x, y, r: 0.5, m: 1.5, vx: 1.5 - 0.25 * i, vy: 0.25 * i - 1.25 });
  }
  world.advance({ untilTime: 4.5 });
  kept.push(world);
}

/** @internal The kept witness (for shapeWitness.test.ts). */
export function shapeWitness(): World | undefined {
  return kept[0];
}
