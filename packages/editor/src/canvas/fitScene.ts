/**
 * Fit (zoom to scene): the view that shows everything in a frame, discs with their radius, lines by
 * their two defining points, points. The view spans at least FIT_MIN_RADII of the scene's typical
 * radius (the median disc's) along its longer side, so a lone disc looks like a disc in a space (a
 * fifth of the view's width), not a disc filling it; a scene wider than that is fitted to its bounds
 * as before (every preset but the original demo, whose two discs of radius 100 now get room to move
 * in: 10 radii across). The median, not the largest: one big disc with small ones near it is fitted
 * to their bounds, not shrunk to a fifth of the view. A scene of lines and points only is fitted to
 * their bounds (points and lines keep their pixel size at any zoom; a lone point keeps the default
 * scale), and an empty scene gets the default view. A body far from the rest stays in view (drawn at
 * least as a dot): Fit shows everything, it never drops an outlier. While the persistent notices
 * hang over the canvas's top (StageNotices.tsx), Fit leaves that strip out, up to half the canvas:
 * the scene is fitted into what is left in view (a fitted scene was partly under a notice).
 */
import { F_R, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { View } from "../store/uiStore";
import { frameBounds } from "./hitTest";
import { fit, type Size } from "./viewTransform";

/** The longer side of a fitted view spans at least this many radii of the median disc. */
export const FIT_MIN_RADII = 10;

/** The least world extent Fit shows for this frame (0 when it has no disc). */
export function fitMinExtent(f: Frame | null): number {
  const n = f?.ids.length ?? 0;
  if (!f || n === 0) return 0;
  const radii = new Float64Array(n);
  for (let i = 0; i < n; i++) radii[i] = f.data[i * FRAME_STRIDE + F_R]!;
  radii.sort(); // numeric for a typed array; Fit is rare (a load, a resize while fitted)
  return FIT_MIN_RADII * radii[(n - 1) >> 1]!;
}

/** The most of the canvas's height that Fit leaves out for a strip covered at its top: a scene is
 *  never fitted into less than the other half (what a notice covers beyond that, in a window too
 *  short for it, is the reader's to dismiss). */
export const FIT_MAX_COVERED = 0.5;

/** The view that fits frame `f` into a canvas of `size` whose top `coveredTop` CSS pixels are
 *  covered (the persistent notices; 0: none). */
export function fitFrame(f: Frame | null, size: Size, coveredTop = 0): View {
  const covered = Math.min(Math.max(coveredTop, 0), FIT_MAX_COVERED * size.height);
  return fit(frameBounds(f), size, undefined, fitMinExtent(f), covered);
}
