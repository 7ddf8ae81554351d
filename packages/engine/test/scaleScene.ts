/**
 * Scaling a scene (test support): lengths by s and time by k. Positions, radii and obstacle
 * coordinates × s, velocities × s/k, the friction field g and gravity × s/k^2; masses and mu
 * unchanged. Physics is invariant under it: the scaled scene's events are the original's at times
 * × k, contact points × s, the same normals, impulses × s/k. With s and k powers of two every
 * product is exact (no over- or underflow within the World's magnitude bounds).
 */
import { FIELD_MIN, MAGNITUDE_MAX, RADIUS_MIN, SPEED_MIN } from "../src/tolerances.js";
import type { SceneSpec } from "./referenceWorld.js";

export function scaleScene(spec: SceneSpec, s: number, k: number): SceneSpec {
  const v = s / k;
  const a = s / (k * k);
  return {
    g: spec.g * a,
    gravity: [spec.gravity[0] * a, spec.gravity[1] * a],
    bodies: spec.bodies.map((b) => ({
      ...b,
      x: b.x * s,
      y: b.y * s,
      vx: b.vx * v,
      vy: b.vy * v,
      r: b.r * s,
    })),
    lines: spec.lines.map((l) => ({
      ...l,
      p1: [l.p1[0] * s, l.p1[1] * s],
      p2: [l.p2[0] * s, l.p2[1] * s],
    })),
    points: spec.points.map((p) => ({ ...p, p: [p.p[0] * s, p.p[1] * s] })),
  };
}

/** floor(log2(x)) for a positive finite x, exactly (no Math.log2 rounding). */
function exponent(x: number): number {
  let e = 0;
  let m = x;
  while (m >= 2) {
    m /= 2;
    e++;
  }
  while (m < 1) {
    m *= 2;
    e--;
  }
  return e;
}

/**
 * The range [lo, hi] of exponents `a` (within [-limit, limit]) for which the scene scaled by
 * s = 2^a·f, k = 2^b·f' (f, f' in [1, 2)) stays within the World's edit bounds (tolerances.ts):
 * every length and rate at most MAGNITUDE_MAX, radii at least RADIUS_MIN, non-zero speeds at least
 * SPEED_MIN, non-zero fields (g, gravity) at least FIELD_MIN. Empty (lo > hi) when no `a` fits.
 */
export function lengthExponents(spec: SceneSpec, b: number, limit: number): [number, number] {
  let maxLen = 0;
  let minR = Number.POSITIVE_INFINITY;
  let maxV = 0;
  let minV = Number.POSITIVE_INFINITY;
  const len = (x: number): void => {
    maxLen = Math.max(maxLen, Math.abs(x));
  };
  for (const body of spec.bodies) {
    len(body.x);
    len(body.y);
    len(body.r);
    minR = Math.min(minR, body.r);
    for (const v of [body.vx, body.vy])
      if (v !== 0) {
        maxV = Math.max(maxV, Math.abs(v));
        minV = Math.min(minV, Math.abs(v));
      }
  }
  for (const l of spec.lines) for (const x of [...l.p1, ...l.p2]) len(x);
  for (const p of spec.points) for (const x of p.p) len(x);
  const maxA = Math.max(spec.g, Math.abs(spec.gravity[0]), Math.abs(spec.gravity[1]));
  // Factors f in [1, 2) take a value up to one binade higher: keep one binade of room at the top,
  // and the bottom needs none (f >= 1); k's factor only lowers rates (room at the bottom).
  const top = exponent(MAGNITUDE_MAX) - 1;
  let lo = -limit;
  let hi = limit;
  if (maxLen > 0) hi = Math.min(hi, top - exponent(maxLen) - 1);
  if (minR < Number.POSITIVE_INFINITY) lo = Math.max(lo, exponent(RADIUS_MIN) + 1 - exponent(minR));
  if (maxV > 0) {
    hi = Math.min(hi, top - exponent(maxV) - 1 + b);
    lo = Math.max(lo, exponent(SPEED_MIN) + 2 - exponent(minV) + b);
  }
  if (maxA > 0) hi = Math.min(hi, top - exponent(maxA) - 1 + 2 * b);
  // Non-zero fields at least FIELD_MIN (k's factor lowers them by up to two binades).
  const fields = [spec.g, Math.abs(spec.gravity[0]), Math.abs(spec.gravity[1])].filter((a) => a > 0);
  if (fields.length > 0) lo = Math.max(lo, exponent(FIELD_MIN) + 3 - exponent(Math.min(...fields)) + 2 * b);
  return [lo, hi];
}
