/**
 * Overlap tests used when validating edits: disc–disc, disc–line (line, ray, segment) and disc–point.
 * A disc overlaps when it reaches inside the other by more than OVERLAP_REL of the contact distance
 * (see tolerances.ts); touching is allowed.
 */
import { OVERLAP_REL } from "../tolerances.js";
import type { LineKind, Vec2 } from "./types.js";

const KEEP = (1 - OVERLAP_REL) * (1 - OVERLAP_REL);

export function discsOverlap(
  ax: number,
  ay: number,
  ar: number,
  bx: number,
  by: number,
  br: number,
): boolean {
  const dx = bx - ax;
  const dy = by - ay;
  const s = ar + br;
  return dx * dx + dy * dy < s * s * KEEP;
}

/** Squared distance from (x, y) to the line of the given kind through p1, p2 (p1 != p2). */
function distance2ToLine(x: number, y: number, p1: Vec2, p2: Vec2, kind: LineKind): number {
  const ux = p2[0] - p1[0];
  const uy = p2[1] - p1[1];
  const wx = x - p1[0];
  const wy = y - p1[1];
  let t = (wx * ux + wy * uy) / (ux * ux + uy * uy);
  if (kind !== "line" && t < 0) t = 0;
  if (kind === "segment" && t > 1) t = 1;
  const dx = wx - t * ux;
  const dy = wy - t * uy;
  return dx * dx + dy * dy;
}

export function discOverlapsLine(
  x: number,
  y: number,
  r: number,
  p1: Vec2,
  p2: Vec2,
  kind: LineKind,
): boolean {
  return distance2ToLine(x, y, p1, p2, kind) < r * r * KEEP;
}

export function discOverlapsPoint(x: number, y: number, r: number, p: Vec2): boolean {
  const dx = p[0] - x;
  const dy = p[1] - y;
  return dx * dx + dy * dy < r * r * KEEP;
}
