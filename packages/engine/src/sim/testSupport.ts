/**
 * Helpers for the World's tests (not built, not packed): the totals a collision must keep.
 */
import type { BodyState } from "./types.js";

/** Kinetic energy and momentum of the bodies: { energy, px, py }. */
export function totals(bodies: readonly BodyState[]): { energy: number; px: number; py: number } {
  let energy = 0;
  let px = 0;
  let py = 0;
  for (const s of bodies) {
    energy += 0.5 * s.m * (s.vx * s.vx + s.vy * s.vy);
    px += s.m * s.vx;
    py += s.m * s.vy;
  }
  return { energy, px, py };
}
