/**
 * Build a World from a SceneSpec (test support), optionally in a permuted insertion order and
 * starting at a given time (default 0).
 */
import { World } from "../src/sim/world.js";
import type { SceneSpec } from "./referenceWorld.js";

export function worldFromSpec(spec: SceneSpec, order?: (n: number) => number[], time = 0): World {
  const w = new World({ g: spec.g, gravity: spec.gravity, time });
  const perm = (n: number): number[] => (order ? order(n) : [...Array(n).keys()]);
  for (const i of perm(spec.lines.length)) {
    const l = spec.lines[i]!;
    w.addLine(l.id, l.p1, l.p2, l.kind);
  }
  for (const i of perm(spec.points.length)) {
    const p = spec.points[i]!;
    w.addPoint(p.id, p.p);
  }
  for (const i of perm(spec.bodies.length)) {
    const b = spec.bodies[i]!;
    w.addBody(b.id, { x: b.x, y: b.y, r: b.r, m: b.m, mu: b.mu, vx: b.vx, vy: b.vy });
  }
  return w;
}

/**
 * An insertion order for worldFromSpec: each call shuffles 0..n-1 (Fisher-Yates) with a 32-bit LCG
 * seeded by `seed`, its state carried from call to call (lines, then points, then bodies).
 */
export function shuffledOrder(seed: number): (n: number) => number[] {
  let s = seed;
  return (n) => {
    const a = [...Array(n).keys()];
    for (let i = n - 1; i > 0; i--) {
      s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
      const j = s % (i + 1);
      [a[i], a[j]] = [a[j] as number, a[i] as number];
    }
    return a;
  };
}
