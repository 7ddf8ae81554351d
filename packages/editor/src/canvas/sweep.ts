/**
 * Whether a small straight move passes across something: what pointerPlace.ts asks of a rounded
 * place before it takes it, so that a disc or a line smaller than a pixel is never rounded to the
 * far side of a wall or of a disc (clear there too, but a disc aimed inside a box would start
 * outside it). Pure.
 * - segmentMeetsLine(a, b, p1, p2, kind): the segment a→b meets the line, ray or segment p1→p2
 *   (touching counts; a move parallel to it never does).
 * - insideQuad(q, corners): q lies strictly inside the convex hull of four points, which holds the
 *   region a segment sweeps while its ends move in straight lines from (p1, p2) to (a, b).
 * - sidesDiffer(q, p1, p2, a, b): q lies strictly on one side of the line through p1, p2 and strictly
 *   on the other of the line through a, b (the line, or a ray's, swept past q).
 */
import type { LineKind, Vec2 } from "../engineTypes";

/** (b − a) × (q − a): positive when q is left of a→b, 0 on its line. */
function cross(a: Vec2, b: Vec2, q: Vec2): number {
  return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
}

/** Whether the segment a→b meets the line, ray or segment p1→p2 (see the header). */
export function segmentMeetsLine(a: Vec2, b: Vec2, p1: Vec2, p2: Vec2, kind: LineKind): boolean {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const ex = p2[0] - p1[0];
  const ey = p2[1] - p1[1];
  const denom = dx * ey - dy * ex;
  if (denom === 0) return false;
  const wx = p1[0] - a[0];
  const wy = p1[1] - a[1];
  const s = (wx * ey - wy * ex) / denom; // along a→b
  const u = (wx * dy - wy * dx) / denom; // along p1→p2
  if (!(s >= 0 && s <= 1)) return false;
  if (kind === "line") return true;
  return u >= 0 && (kind === "ray" || u <= 1);
}

/** The corners of the convex hull of `pts`, counter-clockwise, without collinear ones (Andrew's
 *  monotone chain). */
function hull(pts: readonly Vec2[]): Vec2[] {
  const sorted = [...pts].sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  const half = (list: Vec2[]): Vec2[] => {
    const out: Vec2[] = [];
    for (const p of list) {
      while (out.length >= 2 && cross(out[out.length - 2] as Vec2, out[out.length - 1] as Vec2, p) <= 0)
        out.pop();
      out.push(p);
    }
    out.pop();
    return out;
  };
  return [...half(sorted), ...half([...sorted].reverse())];
}

/** Whether q lies strictly inside the convex hull of the four corners (see the header). */
export function insideQuad(q: Vec2, corners: readonly [Vec2, Vec2, Vec2, Vec2]): boolean {
  const h = hull(corners);
  if (h.length < 3) return false;
  for (let i = 0; i < h.length; i++)
    if (!(cross(h[i] as Vec2, h[(i + 1) % h.length] as Vec2, q) > 0)) return false;
  return true;
}

/** Whether q is strictly on opposite sides of the line p1p2 and of the line ab. */
export function sidesDiffer(q: Vec2, p1: Vec2, p2: Vec2, a: Vec2, b: Vec2): boolean {
  const before = cross(p1, p2, q);
  const after = cross(a, b, q);
  return (before > 0 && after < 0) || (before < 0 && after > 0);
}
