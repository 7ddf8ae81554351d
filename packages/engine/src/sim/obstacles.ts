/**
 * Static obstacles: points and lines (infinite `line`, `ray` from p1 through p2, `segment`).
 * Rays and segments are solid along their length and at their end points. A line caches its
 * direction, unit normal and squared length; the unit normal gives true signed distances, the
 * unnormalised normal (-ey, ex) is used for reflection so that axis-aligned walls reflect exactly.
 */
import type { Vec2 } from "./types.js";

/** Kind of a line obstacle: infinite `line` through p1 and p2, `ray` from p1 through p2, or `segment` p1–p2. */
export type LineKind = "line" | "ray" | "segment";

export interface Line {
  readonly id: string;
  readonly kind: LineKind;
  readonly x1: number;
  readonly y1: number;
  readonly x2: number;
  readonly y2: number;
  /** Direction p2 - p1 and its squared length. */
  readonly ex: number;
  readonly ey: number;
  readonly ee: number;
  /** Unit normal (-ey, ex) / |e|. */
  readonly nx: number;
  readonly ny: number;
}

export interface Point {
  readonly id: string;
  readonly x: number;
  readonly y: number;
}

export function makeLine(id: string, p1: Vec2, p2: Vec2, kind: LineKind): Line {
  const ex = p2[0] - p1[0];
  const ey = p2[1] - p1[1];
  const ee = ex * ex + ey * ey;
  const len = Math.sqrt(ee);
  return { id, kind, x1: p1[0], y1: p1[1], x2: p2[0], y2: p2[1], ex, ey, ee, nx: -ey / len, ny: ex / len };
}

/** Position parameter of (x, y) projected on the line: 0 at p1, 1 at p2. */
export function lineParameter(line: Line, x: number, y: number): number {
  return ((x - line.x1) * line.ex + (y - line.y1) * line.ey) / line.ee;
}

/** Whether the projection parameter lies on the solid part of the line (its interior). */
export function parameterOnLine(kind: LineKind, lambda: number): boolean {
  if (kind === "line") return true;
  if (kind === "ray") return lambda >= 0;
  return lambda >= 0 && lambda <= 1;
}

/** Distance from (x, y) to the solid part of the line (end points included). */
export function distanceToLine(line: Line, x: number, y: number): number {
  const lambda = lineParameter(line, x, y);
  if (parameterOnLine(line.kind, lambda)) {
    return Math.abs(line.nx * (x - line.x1) + line.ny * (y - line.y1));
  }
  const px = lambda < 0 ? line.x1 : line.x2;
  const py = lambda < 0 ? line.y1 : line.y2;
  return Math.sqrt((x - px) * (x - px) + (y - py) * (y - py));
}
