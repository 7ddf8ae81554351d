// Types of bench/scenes/polydisperse.mjs, so TypeScript tests can build the benchmark's gases.
import type { GasScene } from "./gas.d.mts";

/** A gas scene without the single-radius gas's box and elasticity fields. */
export type PolydisperseScene = Omit<GasScene, "box" | "elastic">;
export const RADIUS_LAWS: Record<string, (i: number, rnd: () => number) => number>;
export function polydisperseGas(options: {
  law: string;
  n?: number;
  packing?: number;
  speed?: number;
  seed?: number;
  span?: number;
}): PolydisperseScene;
