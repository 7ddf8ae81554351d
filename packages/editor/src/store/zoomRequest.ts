/**
 * Fast zooms of the Time slider's window (timeWindow.ts), for getting from a long history (a
 * timeline computed to 1e9 s) down to a few seconds in one or a few gestures instead of ~28 halvings:
 *
 * - `zoomBy`: the span times any factor (the wheel over the slider), around the current time t,
 *   which keeps its place on the slider (the thumb does not move), as the Zoom buttons do. A factor
 *   of 1/2 is Zoom in's step and 2 Zoom out's (to rounding).
 * - `zoomToSpan`: a window of a typed width centred on t (the user asks for "5 s around now");
 *   `smallestSpanAt`: the narrowest such window (a narrower width is widened to it).
 *
 * Both stay inside [0, end] (end: where the history ends, timeWindowGuard's historyEnd), never go
 * below the smallest span (minSpan) and give the whole history (null) once the window would cover
 * it. They never leave t out of the window (the guard would turn the page away from the request).
 * `wheelZoomFactor` turns a wheel event's delta into a factor. Pure functions.
 */
import { fitInside, minSpan, type TimeWindow, viewRange } from "./timeWindow";

const clamp = (x: number, lo: number, hi: number): number => Math.min(Math.max(x, lo), hi);

/** The same window as `w` when `next` spans the same range (no store update for a no-op). */
const same = (w: TimeWindow | null, next: TimeWindow | null): TimeWindow | null =>
  w !== null && next !== null && next.lo === w.lo && next.hi === w.hi ? w : next;

/**
 * The window of `factor` times the span around t (kept at its place on the slider), inside the
 * window when zooming in and shifted inside [0, end] when zooming out, at least minSpan wide; null
 * (the whole history, [0, end]) once it would cover [0, end]; `w` itself when nothing changes (at
 * the smallest span, on an empty history, a factor that is not positive).
 */
export function zoomBy(w: TimeWindow | null, factor: number, t: number, end: number): TimeWindow | null {
  const r = viewRange(w, end);
  const span = r.hi - r.lo;
  if (!(span > 0) || !(factor > 0) || factor === 1 || !Number.isFinite(factor)) return w;
  if (w === null && factor > 1) return null;
  const next = Math.max(span * factor, minSpan(r.hi));
  if (factor < 1 && !(next < span)) return w;
  const x = clamp(t, r.lo, r.hi);
  const lo = x - (x - r.lo) * (next / span);
  // zooming in stays inside the window (as Zoom in does: a page turned into the computation reaches
  // past the horizon, and shifting it inside would move the thumb); zooming out stays in the history
  return same(w, factor < 1 ? { lo, hi: Math.min(lo + next, r.hi) } : fitInside(lo, next, end));
}

/**
 * A window `span` seconds wide centred on t (shifted inside [0, end], at least minSpan wide); null
 * (the whole history) when it would cover [0, end] (an infinite span too); `w` itself for a span
 * that is not a positive number or a window the same as `w`.
 */
export function zoomToSpan(w: TimeWindow | null, span: number, t: number, end: number): TimeWindow | null {
  if (!(span > 0)) return w;
  const x = clamp(t, 0, end);
  const s = Math.max(span, smallestSpanAt(span, t, end));
  return same(w, fitInside(x - s / 2, s, end));
}

/**
 * The smallest width a window of `span` seconds centred on t (zoomToSpan) can have: minSpan at its
 * far end. A narrower typed width is widened to it.
 */
export function smallestSpanAt(span: number, t: number, end: number): number {
  return minSpan(clamp(t, 0, end) + span / 2);
}

/** Wheel pixels for one line (deltaMode 1, Firefox: 3 lines a notch) and one page (deltaMode 2). */
const LINE_PX = 100 / 3;
const PAGE_PX = 800;
/** Wheel pixels (one notch of a mouse wheel: 100 in Chromium on Windows and macOS) per factor of 4. */
const PX_PER_QUADRUPLING = 100;
/** At most this many pixels count from one wheel event (a page-mode event is not a 2^16 zoom). */
const MAX_PX = 300;

/**
 * The zoom factor for a wheel event's vertical delta: up (negative) zooms in, down zooms out; one
 * mouse-wheel notch is 4× (two button presses; 1e9 s to 4 s in 14 notches), a touchpad's small
 * deltas zoom smoothly; at most 64× per event.
 */
export function wheelZoomFactor(deltaY: number, deltaMode = 0): number {
  const px = deltaY * (deltaMode === 1 ? LINE_PX : deltaMode === 2 ? PAGE_PX : 1);
  if (!Number.isFinite(px)) return 1;
  return 4 ** (clamp(px, -MAX_PX, MAX_PX) / PX_PER_QUADRUPLING);
}
