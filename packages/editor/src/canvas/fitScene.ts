/**
 * Fit (zoom to scene): the view that shows everything in a frame, discs with their radius, lines by
 * their two defining points, points. The view spans at least FIT_MIN_RADII of the largest radius
 * along its longer side, so a lone disc looks like a disc in a space (a fifth of the view's width),
 * not a disc filling it; a scene wider than that is fitted to its bounds as before (every preset but
 * the original demo, whose two discs of radius 100 now get room to move in: 10 radii across). A scene of lines and
 * points only is fitted to their bounds (points and lines keep their pixel size at any zoom; a lone
 * point keeps the default scale), and an empty scene gets the default view. A body far from the
 * rest stays in view (drawn at least as a dot): Fit shows everything, it never drops an outlier.
 */
import { F_R, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { View } from "../store/uiStore";
import { frameBounds } from "./hitTest";
import { fit, type Size } from "./viewTransform";

/** The longer side of a fitted view spans at least this many radii of the largest disc. */
export const FIT_MIN_RADII = 10;

/** The least world extent Fit shows for this frame (0 when it has no disc). */
export function fitMinExtent(f: Frame | null): number {
  if (!f) return 0;
  let r = 0;
  for (let i = 0; i < f.ids.length; i++) r = Math.max(r, f.data[i * FRAME_STRIDE + F_R]!);
  return FIT_MIN_RADII * r;
}

export function fitFrame(f: Frame | null, size: Size): View {
  return fit(frameBounds(f), size, undefined, fitMinExtent(f));
}
