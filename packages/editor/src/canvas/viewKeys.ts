/**
 * What the scene view's keys do to the view and the selection (shortcuts.ts runs them): a pan by a
 * step of screen pixels, a zoom about the canvas centre, the next or previous body in the Bodies
 * table's order (natural id order, wrapping round), and the view moved just enough to show a body
 * the keyboard selected off screen. Pure functions of the view and the frame's ids and places.
 */
import { naturalOrder } from "../panels/naturalOrder";
import type { Selection, View } from "../store/uiStore";
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

/**
 * The body after (dir 1) or before (dir −1) the selected one in natural id order, wrapping round;
 * with no body selected, the first (or the last). Null when there is no body.
 */
export function nextBody(ids: readonly string[], selection: Selection, dir: 1 | -1): string | null {
  if (ids.length === 0) return null;
  const order = naturalOrder(ids).map((i) => ids[i]!);
  const at = selection?.kind === "body" ? order.indexOf(selection.id) : -1;
  if (at < 0) return dir === 1 ? order[0]! : order[order.length - 1]!;
  return order[(at + dir + order.length) % order.length]!;
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
