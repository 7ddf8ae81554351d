// Types of bench/scenes/polydisperse.mjs, so TypeScript tests can build the benchmark's gases.
import type { StressBody, StressWall } from "../stress/cases.d.mts";

export interface PolydisperseScene {
  id: string;
  title: string;
  description: string;
  span: number;
  g: number;
  gravity: [number, number];
  bodies: StressBody[];
  walls: StressWall[];
}
export const RADIUS_LAWS: Record<string, (i: number, rnd: () => number) => number>;
export function polydisperseGas(options: {
  law: string;
  n?: number;
  packing?: number;
  speed?: number;
  seed?: number;
  span?: number;
}): PolydisperseScene;
