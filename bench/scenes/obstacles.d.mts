// Types of bench/scenes/obstacles.mjs, so TypeScript tests can build the benchmark's obstacle scenes.
import type { GasScene } from "./gas.d.mts";

/** A scene of the engine-neutral format with point pegs beside its walls. */
export interface ObstacleScene extends GasScene {
  points: { id: string; p: [number, number] }[];
  exact: null;
}
export function maze(options?: {
  discs?: number;
  segments?: number;
  seed?: number;
  span?: number;
}): ObstacleScene;
export function galton(options?: {
  balls?: number;
  pegs?: number;
  seed?: number;
  span?: number;
}): ObstacleScene;
