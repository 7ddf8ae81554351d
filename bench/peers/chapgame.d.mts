// Types of the part of bench/peers/chapgame.mjs that TypeScript tests use.
import type { Optimizations, World } from "../../packages/engine/src/index.js";
import type { StressBody, StressWall } from "../stress/cases.d.mts";

export function buildWorld(
  engine: { World: typeof World },
  scene: { g: number; gravity: [number, number]; bodies: StressBody[]; walls: StressWall[] },
  worldOptions?: { optimizations?: Optimizations },
): World;
