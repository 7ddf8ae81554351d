/**
 * Where a new disc, point or horizontal segment can go near a given place (the centre of the view)
 * without touching anything in the frame: the place itself if it is free, else the nearest free
 * candidate on rings around it (ring k at k steps, 8k candidates). The engine refuses a disc that
 * overlaps a disc, a line or a point, so the Add buttons ask here first; blockerAt says what is in
 * the way of a place (the keyboard's add at the centre, canvas/addAtCentre.ts, names it), and
 * lineBlocker what is in the way of a line, ray or segment (a drag of the Line tools). With a `grid`
 * (the pointer's precision, pointerGrid.ts) each candidate is rounded to it before it is checked, so
 * the place returned is both round and free. Pure.
 */
import type { LineKind, Vec2 } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { Selection } from "../store/uiStore";
import { distanceToLine } from "./clip";
import { roundPoint } from "./pointerGrid";

export type NewShape = { kind: "disc"; r: number } | { kind: "point" } | { kind: "segment"; half: number };

/** Rings of candidates tried around the place before giving up. */
export const FREE_SPOT_RINGS = 40;
/** Clearance kept between the new object and anything else, as a share of the step. */
const CLEARANCE = 0.1;

/**
 * What `shape` at `c` would come within `gap` of in `f` (a disc first, then a line, then a point), or
 * null. `except`: a disc to leave out (the one being moved).
 */
export function blockerAt(
  f: Frame,
  shape: NewShape,
  c: Vec2,
  gap: number,
  except: string | null = null,
): NonNullable<Selection> | null {
  const d = f.data;
  const r = shape.kind === "disc" ? shape.r : 0;
  const p1: Vec2 = shape.kind === "segment" ? [c[0] - shape.half, c[1]] : c;
  const p2: Vec2 = shape.kind === "segment" ? [c[0] + shape.half, c[1]] : c;
  for (let i = 0; i < f.ids.length; i++) {
    if (f.ids[i] === except) continue;
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

/** The first disc of `f` that the line, ray or segment p1→p2 would overlap (touching is free), or null. */
export function lineBlocker(f: Frame, p1: Vec2, p2: Vec2, kind: LineKind): NonNullable<Selection> | null {
  const d = f.data;
  for (let i = 0; i < f.ids.length; i++) {
    const o = i * FRAME_STRIDE;
    if (distanceToLine([d[o + F_X]!, d[o + F_Y]!], p1, p2, kind) < d[o + F_R]!)
      return { kind: "body", id: f.ids[i]! };
  }
  return null;
}

/** True when `shape` at `c` keeps at least `gap` from every disc, line and point of `f`. */
function fits(f: Frame, shape: NewShape, c: Vec2, gap: number): boolean {
  return blockerAt(f, shape, c, gap) === null;
}

/**
 * The free place for `shape` nearest to `at` (on rings `step` apart), or null when none of
 * FREE_SPOT_RINGS rings has one. With no frame, `at` itself. Each candidate is rounded to `grid`
 * first, when given (a power of ten, pointerGrid.ts).
 */
export function freeSpot(
  f: Frame | null,
  shape: NewShape,
  at: Vec2,
  step: number,
  grid?: number,
): Vec2 | null {
  const place = (p: Vec2): Vec2 => (grid === undefined ? p : roundPoint(p, grid));
  if (!f) return place(at);
  const gap = step * CLEARANCE;
  const c0 = place(at);
  if (fits(f, shape, c0, gap)) return c0;
  for (let k = 1; k <= FREE_SPOT_RINGS; k++) {
    const n = 8 * k;
    for (let j = 0; j < n; j++) {
      const a = (2 * Math.PI * j) / n;
      const c = place([at[0] + k * step * Math.cos(a), at[1] + k * step * Math.sin(a)]);
      if (fits(f, shape, c, gap)) return c;
    }
  }
  return null;
}
