/** What is under a world point in a Frame: the topmost disc, else a point, else a line. Pure. */
import type { Vec2 } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { Selection } from "../store/uiStore";
import { distanceToLine } from "./clip";
import { type Bounds, include } from "./viewTransform";

/** `tolerance` is in world units (a few pixels divided by the view scale). */
export function hitTest(f: Frame | null, q: Vec2, tolerance: number): Selection {
  if (!f) return null;
  const d = f.data;
  for (let i = f.ids.length - 1; i >= 0; i--) {
    const b = i * FRAME_STRIDE;
    const dx = q[0] - d[b + F_X]!;
    const dy = q[1] - d[b + F_Y]!;
    const r = d[b + F_R]! + tolerance;
    if (dx * dx + dy * dy <= r * r) return { kind: "body", id: f.ids[i]! };
  }
  for (const p of f.points)
    if (Math.hypot(q[0] - p.p[0], q[1] - p.p[1]) <= tolerance) return { kind: "point", id: p.id };
  for (const l of f.lines)
    if (distanceToLine(q, l.p1, l.p2, l.kind) <= tolerance) return { kind: "line", id: l.id };
  return null;
}

/** Index of body `id` in the frame, or -1. */
export function bodyIndex(f: Frame | null, id: string): number {
  return f ? f.ids.indexOf(id) : -1;
}

/** Bounds of everything in the frame (discs with their radius, both ends of lines, points). */
export function frameBounds(f: Frame | null): Bounds | null {
  if (!f) return null;
  let b: Bounds | null = null;
  const d = f.data;
  for (let i = 0; i < f.ids.length; i++) {
    const o = i * FRAME_STRIDE;
    b = include(b, d[o + F_X]!, d[o + F_Y]!, d[o + F_R]!);
  }
  for (const l of f.lines) {
    b = include(b, l.p1[0], l.p1[1]);
    b = include(b, l.p2[0], l.p2[1]);
  }
  for (const p of f.points) b = include(b, p.p[0], p.p[1]);
  return b;
}
