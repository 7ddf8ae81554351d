/**
 * Random scenes for property tests (test support): a box of four segments with discs inside, some
 * touching in rows, optional inner points, segment, ray or line, and one of three force modes
 * (none, friction, gravity). Fully determined by the seed (a 32-bit LCG, no Math.random).
 */
import type { SceneSpec } from "./referenceWorld.js";

export interface RandomSceneOptions {
  /** Bodies asked for: uniform in [minBodies (default 1), maxBodies]; fewer if they do not fit. */
  minBodies?: number;
  maxBodies: number;
  mode: "elastic" | "friction" | "gravity" | "any";
  obstacles: boolean;
  infiniteMasses: boolean;
}

export function lcg(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 4294967296;
  };
}

export function randomScene(seed: number, opts: RandomSceneOptions): SceneSpec {
  const rnd = lcg(seed);
  const uni = (a: number, b: number): number => a + (b - a) * rnd();
  const L = uni(30, 80);
  const mode =
    opts.mode === "any" ? (["elastic", "friction", "gravity"] as const)[Math.floor(rnd() * 3)] : opts.mode;
  const spec: SceneSpec = {
    g: mode === "friction" ? uni(0.5, 10) : 0,
    gravity: mode === "gravity" ? [uni(-2, 2), -uni(1, 10)] : [0, 0],
    bodies: [],
    lines: [
      { id: "wS", p1: [0, 0], p2: [L, 0], kind: "segment" },
      { id: "wE", p1: [L, 0], p2: [L, L], kind: "segment" },
      { id: "wN", p1: [L, L], p2: [0, L], kind: "segment" },
      { id: "wW", p1: [0, L], p2: [0, 0], kind: "segment" },
    ],
    points: [],
  };
  if (opts.obstacles) {
    const nPoints = Math.floor(rnd() * 3);
    for (let i = 0; i < nPoints; i++)
      spec.points.push({ id: `p${i}`, p: [uni(0.2 * L, 0.8 * L), uni(0.2 * L, 0.8 * L)] });
    if (rnd() < 0.5)
      spec.lines.push({
        id: "seg",
        p1: [uni(0.2, 0.5) * L, uni(0.2, 0.8) * L],
        p2: [uni(0.5, 0.8) * L, uni(0.2, 0.8) * L],
        kind: "segment",
      });
    if (rnd() < 0.3)
      spec.lines.push({
        id: "ray",
        p1: [0.5 * L, 0.3 * L],
        p2: [0.5 * L + uni(-1, 1), 0.3 * L + 1],
        kind: "ray",
      });
    if (rnd() < 0.2)
      spec.lines.push({ id: "line", p1: [0, uni(0.3, 0.7) * L], p2: [L, uni(0.3, 0.7) * L], kind: "line" });
  }
  const lo = opts.minBodies ?? 1;
  const n = lo + Math.floor(rnd() * (opts.maxBodies - lo + 1));
  const clear = (x: number, y: number, r: number): boolean => {
    for (const b of spec.bodies) if ((b.x - x) ** 2 + (b.y - y) ** 2 < (b.r + r) ** 2) return false;
    for (const p of spec.points) if ((p.p[0] - x) ** 2 + (p.p[1] - y) ** 2 < r * r) return false;
    for (const l of spec.lines) if (distanceToLine(l, x, y) < r) return false;
    return true;
  };
  for (let i = 0, tries = 0; spec.bodies.length < n && tries < 50 * n; tries++) {
    const r = uni(0.5, 3);
    const touching = spec.bodies.length > 0 && rnd() < 0.25;
    const prev = spec.bodies[spec.bodies.length - 1];
    const x = touching && prev ? prev.x + prev.r + r : uni(r, L - r);
    const y = touching && prev ? prev.y : uni(r, L - r);
    if (!clear(x, y, r)) continue;
    const m = opts.infiniteMasses && rnd() < 0.1 ? Number.POSITIVE_INFINITY : uni(0.5, 5);
    const still = rnd() < 0.2;
    spec.bodies.push({
      id: `b${String(i++).padStart(2, "0")}`,
      x,
      y,
      vx: still ? 0 : uni(-10, 10),
      vy: still ? 0 : uni(-10, 10),
      r,
      m,
      mu: mode === "friction" ? uni(0, 0.5) : 0,
    });
  }
  return spec;
}

/** Distance from (x, y) to line l of any kind (a ray or segment: its nearest point, end points included). */
export function distanceToLine(l: SceneSpec["lines"][number], x: number, y: number): number {
  const ex = l.p2[0] - l.p1[0];
  const ey = l.p2[1] - l.p1[1];
  let t = ((x - l.p1[0]) * ex + (y - l.p1[1]) * ey) / (ex * ex + ey * ey);
  if (l.kind !== "line") t = Math.max(0, l.kind === "segment" ? Math.min(1, t) : t);
  return Math.hypot(x - (l.p1[0] + t * ex), y - (l.p1[1] + t * ey));
}
