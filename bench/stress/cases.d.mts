// Types of bench/stress/cases.mjs, so the TypeScript stress tests can import the same scenes.
export interface StressBody {
  id: string;
  x: number;
  y: number;
  r: number;
  m: number;
  vx: number;
  vy: number;
  mu: number;
}
export interface StressWall {
  id: string;
  p1: [number, number];
  p2: [number, number];
  kind: "line" | "ray" | "segment";
  inside: [number, number];
  thickness: number;
}
export interface StressScene {
  id: string;
  span: number;
  g: number;
  gravity: [number, number];
  bodies: StressBody[];
  walls: StressWall[];
  box: { x0: number; y0: number; x1: number; y1: number } | null;
  tolerance: number;
}
export function grazing(lanes?: number): StressScene;
export function nearSimultaneous(lanes?: number): StressScene;
export function roundOffContacts(rings?: number, n?: number): StressScene;
export function largeOffset(n?: number, seed?: number): StressScene;
export function massRatio(ratio: number, n?: number, seed?: number): StressScene;
export function highSpeed(speed: number, n?: number, fast?: number, seed?: number): StressScene;
