// Types of bench/engine/minimalGas.mjs (the benchmark's ceiling loop), for its test.
import type { GasScene } from "../scenes/gas.d.mts";

export interface MinimalGas {
  /** Process queue items until `count` collisions (disc or wall); returns count. */
  advance(count: number): number;
  time(): number;
  state(): { x: number; y: number; vx: number; vy: number }[];
  /** Each disc's queued key (+Infinity when not queued). */
  queueKeys(): Float64Array;
  /** Calendar width, ring length and rebuilds so far. */
  queueStats(): { width: number; buckets: number; rebuilds: number };
}
/** `onPop(disc, key)` is called for every popped item before it is processed (tests only). */
export function createMinimalGas(
  scene: GasScene,
  onPop?: ((disc: number, key: number) => void) | null,
): MinimalGas;
