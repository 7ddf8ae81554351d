/**
 * Clipping of lines, rays and segments to a rectangle (Liang–Barsky), so infinite lines and rays
 * are drawn exactly to the view's edge. Pure.
 */
import type { LineKind, Vec2 } from "../engineTypes";
import type { Bounds } from "./viewTransform";

/** The visible part of p1→p2 (as a line, ray from p1, or segment) inside `r`, or null if none. */
export function clipToRect(p1: Vec2, p2: Vec2, kind: LineKind, r: Bounds): [Vec2, Vec2] | null {
  const dx = p2[0] - p1[0];
  const dy = p2[1] - p1[1];
  let lo = kind === "line" ? Number.NEGATIVE_INFINITY : 0;
  let hi = kind === "segment" ? 1 : Number.POSITIVE_INFINITY;
  const edges: [number, number][] = [
    [-dx, p1[0] - r.minX],
    [dx, r.maxX - p1[0]],
    [-dy, p1[1] - r.minY],
    [dy, r.maxY - p1[1]],
  ];
  for (const [p, q] of edges) {
    if (p === 0) {
      if (q < 0) return null;
    } else {
      const s = q / p;
      if (p < 0) lo = Math.max(lo, s);
      else hi = Math.min(hi, s);
    }
  }
  if (lo > hi || !Number.isFinite(lo) || !Number.isFinite(hi)) return null;
  return [
    [p1[0] + lo * dx, p1[1] + lo * dy],
    [p1[0] + hi * dx, p1[1] + hi * dy],
  ];
}

/** The point of the line, ray or segment p1→p2 nearest to q. */
export function nearestOnLine(q: Vec2, p1: Vec2, p2: Vec2, kind: LineKind): Vec2 {
  const dx = p2[0] - p1[0];
  const dy = p2[1] - p1[1];
  const len2 = dx * dx + dy * dy;
  let s = len2 === 0 ? 0 : ((q[0] - p1[0]) * dx + (q[1] - p1[1]) * dy) / len2;
  if (kind !== "line") s = Math.max(s, 0);
  if (kind === "segment") s = Math.min(s, 1);
  return [p1[0] + s * dx, p1[1] + s * dy];
}

/** Distance from q to the line, ray or segment p1→p2. */
export function distanceToLine(q: Vec2, p1: Vec2, p2: Vec2, kind: LineKind): number {
  const [x, y] = nearestOnLine(q, p1, p2, kind);
  return Math.hypot(q[0] - x, q[1] - y);
}
