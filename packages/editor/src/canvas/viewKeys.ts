/**
 * What the scene view's keys do to the view and the selection (shortcuts.ts runs them): a pan by a
 * step of screen pixels, a zoom about the canvas centre, the next or previous object in the tables'
 * order (bodies, lines, then points, wrapping round), and the view moved just enough to show an
 * object the keyboard selected off screen. Pure functions of the view and the frame's ids and places.
 */
import type { Vec2 } from "../engineTypes";
import { naturalOrder } from "../panels/naturalOrder";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { Selection, View } from "../store/uiStore";
import { nearestOnLine } from "./clip";
import { MAX_SCALE, MIN_SCALE, type Size, toScreen } from "./viewTransform";

/** Screen pixels an arrow key pans the view by (Shift: PAN_STEP_PX * PAN_FAST). */
export const PAN_STEP_PX = 40;
export const PAN_FAST = 5;
/** The factor + and − zoom the view by. */
export const ZOOM_STEP = 1.25;

const DIRS: Record<string, [number, number]> = {
  ArrowLeft: [1, 0],
  ArrowRight: [-1, 0],
  ArrowUp: [0, 1],
  ArrowDown: [0, -1],
};

/**
 * The view after an arrow key: the camera moves the way the arrow points (→ shows what is to the
 * right), so the content moves the other way, as a drag of the empty canvas moves it.
 */
export function panByKey(v: View, key: string, fast: boolean): View {
  const d = DIRS[key];
  if (!d) return v;
  const px = PAN_STEP_PX * (fast ? PAN_FAST : 1);
  return { scale: v.scale, cx: v.cx - (d[0] * px) / v.scale, cy: v.cy + (d[1] * px) / v.scale };
}

/** The view zoomed `steps` ZOOM_STEPs (negative: out) about the canvas centre, within the scale limits. */
export function zoomByKey(v: View, steps: number): View {
  const scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, v.scale * ZOOM_STEP ** steps));
  return { ...v, scale };
}

/** What N and Shift+N go through: the ids of the bodies, lines and points of the frame shown. */
export interface Selectables {
  bodies: readonly string[];
  lines: readonly string[];
  points: readonly string[];
}

/**
 * The object after (dir 1) or before (dir −1) the selected one in the order of the tables: the
 * bodies, then the lines, then the points, each in its table's order (natural id order), wrapping
 * round from the last point to the first body. With nothing selected, or an object not in the
 * frame, the first (or the last). Null when there is nothing to select.
 */
export function nextObject(
  from: Selectables,
  selection: Selection,
  dir: 1 | -1,
): NonNullable<Selection> | null {
  const order: NonNullable<Selection>[] = [
    ...naturalOrder(from.bodies).map((i) => ({ kind: "body" as const, id: from.bodies[i]! })),
    ...naturalOrder(from.lines).map((i) => ({ kind: "line" as const, id: from.lines[i]! })),
    ...naturalOrder(from.points).map((i) => ({ kind: "point" as const, id: from.points[i]! })),
  ];
  if (order.length === 0) return null;
  const at =
    selection === null ? -1 : order.findIndex((o) => o.kind === selection.kind && o.id === selection.id);
  if (at < 0) return dir === 1 ? order[0]! : order[order.length - 1]!;
  return order[(at + dir + order.length) % order.length]!;
}

/** The ids N and Shift+N go through in the frame `f`. */
export function selectablesOf(f: Frame): Selectables {
  return { bodies: f.ids, lines: f.lines.map((l) => l.id), points: f.points.map((p) => p.id) };
}

/**
 * The place to bring into view for the object `sel` of the frame `f`, as a disc (x, y, r): a body's
 * disc; a point; the point of a line, ray or segment nearest to `centre` (the view's: so a line
 * that crosses the view moves nothing). Null when the frame has no such object.
 */
export function placeOf(
  f: Frame,
  sel: NonNullable<Selection>,
  centre: Vec2,
): [number, number, number] | null {
  if (sel.kind === "body") {
    const i = f.ids.indexOf(sel.id);
    if (i < 0) return null;
    const o = i * FRAME_STRIDE;
    return [f.data[o + F_X]!, f.data[o + F_Y]!, f.data[o + F_R]!];
  }
  if (sel.kind === "point") {
    const p = f.points.find((q) => q.id === sel.id);
    return p ? [p.p[0], p.p[1], 0] : null;
  }
  const l = f.lines.find((q) => q.id === sel.id);
  if (!l) return null;
  const [x, y] = nearestOnLine(centre, l.p1, l.p2, l.kind);
  return [x, y, 0];
}

/**
 * The view moved so the disc at (x, y) of radius r is inside the canvas with `margin` pixels to spare,
 * by as little as it takes; the view itself when it already is. A disc too large to fit is centred.
 */
export function revealDisc(v: View, size: Size, x: number, y: number, r: number, margin = 24): View {
  const [sx, sy] = toScreen(v, size, x, y);
  const rr = r * v.scale + margin;
  const shift = (s: number, extent: number) => {
    if (2 * rr >= extent) return s - extent / 2;
    if (s - rr < 0) return s - rr;
    if (s + rr > extent) return s + rr - extent;
    return 0;
  };
  const dx = shift(sx, size.width);
  const dy = shift(sy, size.height);
  if (dx === 0 && dy === 0) return v;
  return { scale: v.scale, cx: v.cx + dx / v.scale, cy: v.cy - dy / v.scale };
}
