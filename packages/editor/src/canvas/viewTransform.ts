/**
 * Pure view math of the canvas. World coordinates have y up; the screen (CSS pixels) has y down.
 * A View is the world point at the canvas centre and the scale in CSS pixels per world unit.
 */
import type { View } from "../store/uiStore";

export interface Size {
  width: number;
  height: number;
}

export function toScreen(v: View, size: Size, x: number, y: number): [number, number] {
  return [size.width / 2 + (x - v.cx) * v.scale, size.height / 2 - (y - v.cy) * v.scale];
}

export function toWorld(v: View, size: Size, sx: number, sy: number): [number, number] {
  return [v.cx + (sx - size.width / 2) / v.scale, v.cy - (sy - size.height / 2) / v.scale];
}

/** Smallest and largest allowed scale, so zooming can never reach 0 or overflow. */
export const MIN_SCALE = 1e-6;
export const MAX_SCALE = 1e6;

/** Zooms by `factor` keeping the world point under the screen point (sx, sy) where it is. */
export function zoomAt(v: View, size: Size, sx: number, sy: number, factor: number): View {
  const scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, v.scale * factor));
  const [wx, wy] = toWorld(v, size, sx, sy);
  return {
    scale,
    cx: wx - (sx - size.width / 2) / scale,
    cy: wy + (sy - size.height / 2) / scale,
  };
}

/** Moves the view so the content follows a drag of (dx, dy) screen pixels. */
export function pan(v: View, dx: number, dy: number): View {
  return { scale: v.scale, cx: v.cx - dx / v.scale, cy: v.cy + dy / v.scale };
}

export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/**
 * The view that shows `b` whole with `margin` CSS pixels around it. The view spans at least
 * `minExtent` world units along its longer side (so one small disc is not blown up to fill it);
 * a point with no minimum extent gets a default scale, and no bounds the default view. The top
 * `coveredTop` CSS pixels of the canvas are left out (something hangs over them): `b` is fitted
 * into the rest, centred there.
 */
export function fit(b: Bounds | null, size: Size, margin = 24, minExtent = 0, coveredTop = 0): View {
  if (!b || !Number.isFinite(b.minX + b.maxX + b.minY + b.maxY)) return { cx: 0, cy: 0, scale: 1 };
  const w = Math.max(b.maxX - b.minX, 0);
  const h = Math.max(b.maxY - b.minY, 0);
  const availW = Math.max(size.width - 2 * margin, 1);
  const availH = Math.max(size.height - coveredTop - 2 * margin, 1);
  let scale = Math.min(
    w > 0 ? availW / w : Number.POSITIVE_INFINITY,
    h > 0 ? availH / h : Number.POSITIVE_INFINITY,
  );
  if (minExtent > 0) scale = Math.min(scale, Math.max(availW, availH) / minExtent);
  if (!Number.isFinite(scale)) scale = 1;
  scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, scale));
  // the bounds' centre at the centre of the uncovered part, coveredTop / 2 below the canvas's
  const cy = (b.minY + b.maxY) / 2 + (coveredTop > 0 ? coveredTop / 2 / scale : 0);
  return { cx: (b.minX + b.maxX) / 2, cy, scale };
}

/** Grows bounds to include a point (null bounds start from the point). */
export function include(b: Bounds | null, x: number, y: number, pad = 0): Bounds {
  if (!b) return { minX: x - pad, minY: y - pad, maxX: x + pad, maxY: y + pad };
  return {
    minX: Math.min(b.minX, x - pad),
    minY: Math.min(b.minY, y - pad),
    maxX: Math.max(b.maxX, x + pad),
    maxY: Math.max(b.maxY, y + pad),
  };
}
