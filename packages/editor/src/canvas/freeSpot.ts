/**
 * Where a new disc, point or horizontal segment can go near a given place (the centre of the view)
 * without touching anything in the frame: the place itself if it is free, else the nearest free
 * candidate on rings around it (ring k at k steps, 8k candidates). The engine refuses a disc that
 * overlaps a disc, a line or a point, so the Add buttons ask here first; blockerAt says what is in
 * the way of a place (the keyboard's add at the centre, canvas/addAtCentre.ts, names it). Pure.
 */
import type { Vec2 } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { Selection } from "../store/uiStore";
import { distanceToLine } from "./clip";

export type NewShape = { kind: "disc"; r: number } | { kind: "point" } | { kind: "segment"; half: number };

/** Rings of candidates tried around the place before giving up. */
export const FREE_SPOT_RINGS = 40;
/** Clearance kept between the new object and anything else, as a share of the step. */
const CLEARANCE = 0.1;

/** What `shape` at `c` would come within `gap` of in `f` (a disc first, then a line, then a point), or null. */
export function blockerAt(f: Frame, shape: NewShape, c: Vec2, gap: number): NonNullable<Selection> | null {
  const d = f.data;
  const r = shape.kind === "disc" ? shape.r : 0;
  const p1: Vec2 = shape.kind === "segment" ? [c[0] - shape.half, c[1]] : c;
  const p2: Vec2 = shape.kind === "segment" ? [c[0] + shape.half, c[1]] : c;
  for (let i = 0; i < f.ids.length; i++) {
    const o = i * FRAME_STRIDE;
    const q: Vec2 = [d[o + F_X]!, d[o + F_Y]!];
    if (distanceToLine(q, p1, p2, "segment") < d[o + F_R]! + r + gap) return { kind: "body", id: f.ids[i]! };
  }
  if (shape.kind !== "disc") return null; // lines and points may cross or touch each other
  for (const l of f.lines)
    if (distanceToLine(c, l.p1, l.p2, l.kind) < r + gap) return { kind: "line", id: l.id };
  for (const p of f.points)
    if (Math.hypot(c[0] - p.p[0], c[1] - p.p[1]) < r + gap) return { kind: "point", id: p.id };
  return null;
}

/** True when `shape` at `c` keeps at least `gap` from every disc, line and point of `f`. */
function fits(f: Frame, shape: NewShape, c: Vec2, gap: number): boolean {
  return blockerAt(f, shape, c, gap) === null;
}

/**
 * The free place for `shape` nearest to `at` (on rings `step` apart), or null when none of
 * FREE_SPOT_RINGS rings has one. With no frame, `at` itself.
 */
export function freeSpot(f: Frame | null, shape: NewShape, at: Vec2, step: number): Vec2 | null {
  if (!f) return at;
  const gap = step * CLEARANCE;
  if (fits(f, shape, at, gap)) return at;
  for (let k = 1; k <= FREE_SPOT_RINGS; k++) {
    const n = 8 * k;
    for (let j = 0; j < n; j++) {
      const a = (2 * Math.PI * j) / n;
      const c: Vec2 = [at[0] + k * step * Math.cos(a), at[1] + k * step * Math.sin(a)];
      if (fits(f, shape, c, gap)) return c;
    }
  }
  return null;
}
