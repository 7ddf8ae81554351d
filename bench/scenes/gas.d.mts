// Types of bench/scenes/gas.mjs, so TypeScript tests can build the benchmark's gas.
import type { StressBody, StressWall } from "../stress/cases.d.mts";

export interface GasScene {
  id: string;
  title: string;
  description: string;
  span: number;
  g: number;
  gravity: [number, number];
  bodies: StressBody[];
  walls: StressWall[];
  box: { x0: number; y0: number; x1: number; y1: number };
  elastic: boolean;
}
export function gas(options?: {
  n?: number;
  packing?: number;
  speed?: number;
  seed?: number;
  span?: number;
  r?: number;
}): GasScene;
