// Types of bench/engine/minimalGas.mjs (the benchmark's ceiling loop), for its test.
import type { GasScene } from "../scenes/gas.d.mts";

export interface MinimalGas {
  /** Process queue items until `count` collisions (disc or wall); returns count. */
  advance(count: number): number;
  time(): number;
  state(): { x: number; y: number; vx: number; vy: number }[];
}
export function createMinimalGas(scene: GasScene): MinimalGas;
