/**
 * The still bodies a trap's proof (trapWatch.ts, lineWatch.ts) may take as sides or as the end of a
 * crush in line: lines, points and immovable discs at rest, as cores (pocketGeometry.ts) with an
 * order key that also names them; and one scratch core that the scans fill in place, so that they
 * measure every obstacle without allocating one each.
 */
import type { Core, CoreKind } from "./pocketGeometry.js";
import { quoteId } from "./refusalText.js";

/** A side the pocket may have: its core and its order key (which also names it). */
export interface Side {
  core: Core;
  /** Distance from the trapped disc's surface to it. */
  gap: number;
  /** 0 line, 1 point, 2 body (ids are unique per kind). */
  rank: number;
  id: string;
}

/** How a message names a side. */
export function named(side: Side): string {
  return `${side.rank === 0 ? "line" : side.rank === 1 ? "point" : "the immovable body"} ${quoteId(side.id)}`;
}

/** Canonical order of sides: nearer first, then lines, points, bodies, then by id. */
export function before(gap: number, rank: number, id: string, v: Side): boolean {
  if (gap !== v.gap) return gap < v.gap;
  if (rank !== v.rank) return rank < v.rank;
  return id < v.id;
}

/** The scratch core (only one exists: a scan uses it before the next fill). */
export const scratch: { -readonly [K in keyof Core]: Core[K] } = {
  kind: "point",
  x1: 0,
  y1: 0,
  x2: 0,
  y2: 0,
  rad: 0,
};

/** The scratch core, filled with a core of this shape. */
export function fill(kind: CoreKind, x1: number, y1: number, x2: number, y2: number, rad: number): Core {
  scratch.kind = kind;
  scratch.x1 = x1;
  scratch.y1 = y1;
  scratch.x2 = x2;
  scratch.y2 = y2;
  scratch.rad = rad;
  return scratch;
}
