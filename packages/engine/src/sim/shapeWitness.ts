/**
 * The shape witness: one small World, built (never run) when the engine loads and kept for the
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
 * still had it would keep only that one). So the witness is built with fractional options and
 * then given a fraction in each number field a simulation fills with fractions (FRACTION_FIELDS),
 * which moves its parts to the maps those fields end with; its values mean nothing after that, and
 * it is never run. It is not run because a run would leave its own type feedback in the engine's
 * hot functions: a 40-disc run cost 200 to 750 more instructions per collision in the gas that
 * followed (callgrind). shapeWitness.test.ts checks that after Worlds of several kinds ran,
 * the witness's parts still have the same maps as theirs (a field missing from FRACTION_FIELDS
 * fails it).
 */
import type { WorldOptions } from "./types.js";
import type { World } from "./world.js";

/** Options of the witness: fractions, so that the number fields they set are stored as doubles. */
export const WITNESS_OPTIONS: WorldOptions = { g: 0.5, gravity: [0.5, 0.25], time: 0.5 };

/**
 * The parts of a World (by field name) and their number fields that a simulation fills with
 * fractions while they start as small integers: the grid's origin and cell side, the event
 * queue's origin and bucket width, the event record, the Zeno watch's largest mass.
 */
const FRACTION_FIELDS: Readonly<Record<string, readonly string[]>> = {
  grid: ["ox", "oy", "w"],
  heap: ["origin", "w", "invW"],
  ev: ["time", "px", "py", "nx", "ny", "impulse"],
  zeno: ["massHi"],
};

/** Worlds kept alive for the process's lifetime (one: the witness). */
const kept: World[] = [];

/**
 * Make `world` (a new World made with WITNESS_OPTIONS) the witness and keep it: a segment and a
 * disc (so that the obstacles' indexes exist), then a fraction in each of FRACTION_FIELDS.
 */
export function keepAsShapeWitness(world: World): void {
  world.addLine("wall", [6.5, -20.5], [6.5, 20.5], "segment");
  world.addBody("disc", { x: 0.5, y: 0.75, r: 0.5, m: 1.5, vx: 1.5, vy: -1.25 });
  const parts = world as unknown as Record<string, Record<string, number> | undefined>;
  for (const [name, fields] of Object.entries(FRACTION_FIELDS)) {
    const part = parts[name];
    if (part !== undefined) for (const field of fields) part[field] = 0.5;
  }
  kept.push(world);
}

/** @internal The kept witness (for shapeWitness.test.ts). */
export function shapeWitness(): World | undefined {
  return kept[0];
}
