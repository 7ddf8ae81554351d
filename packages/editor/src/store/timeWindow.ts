/**
 * The Time slider's view window: the part [lo, hi] of the history the slider spans, so that a long
 * history (a time typed far ahead) can still be scrubbed second by second. null is the whole
 * history [0, end], the default, which follows the history's end as it grows (the horizon, or during
 * an undo's restore the history being restored: timeWindowGuard's historyEnd). Pure functions; the UI
 * store holds the window (`timeWindow`, not an undo step, not saved) and timeWindowGuard.ts keeps it
 * inside the history and around the current time.
 *
 * - Zoom in halves the span and zoom out doubles it, both around the current time: the time keeps
 *   its place on the slider (the thumb does not move), so zooming in and out again is the same
 *   window. Zooming out to the whole history or more is the whole history (null).
 * - Following the time (`follow`), like turning pages: a time that runs off an edge (playing past
 *   hi, stepping to the next event) turns to the next page of the same span, which starts where the
 *   window ended (backwards: ends where it started), so playback reads the history page by page. A
 *   jump of more than one page (a typed time, a far event step) centres the window on the time.
 *   Either way the new page is shifted inside [0, end of the history], except a page turned forward
 *   while the history grows (playing into the computation): that page is whole, its part past the
 *   end filled in as it is computed. Shifted back, it crept by the computation's lead (about 2 s)
 *   every couple of seconds, the thumb near its right edge. When the history stops growing short of
 *   such a page's end, the page settles back inside it (`settle`): its right edge at the end.
 */

export interface TimeWindow {
  lo: number;
  hi: number;
}

const clamp = (x: number, lo: number, hi: number): number => Math.min(Math.max(x, lo), hi);

/**
 * The range the slider spans: the window, or [0, end] for the whole history (`end`: where the history
 * ends, timeWindowGuard's historyEnd; during an undo's restore, the history being restored).
 */
export function viewRange(w: TimeWindow | null, end: number): TimeWindow {
  return w ?? { lo: 0, hi: end };
}

/**
 * The time a value of the slider stands for: the value clamped to the slider's range. Chromium
 * writes a range input's value to about 15 significant digits, so a thumb at an end of a window
 * whose ends need 16 or 17 (2.5004999999999997) reads just past it (2.5005): the guard turned the
 * page, the thumb under the pointer was at the new page's end, and holding it there turned a page on
 * every pointer move.
 */
export function sliderTime(value: number, w: TimeWindow | null, end: number): number {
  const r = viewRange(w, end);
  return clamp(value, r.lo, Math.max(r.lo, r.hi));
}

/**
 * Smallest span zoom in goes to (s): a billionth of a second, and never so small that the slider's
 * values are only a few floating-point steps apart (1e-12 of the time's size, thousands of steps).
 */
export function minSpan(hi: number): number {
  return Math.max(1e-9, Math.abs(hi) * 1e-12);
}

/** Whether zoom in would narrow the range (a history to zoom into, not at the smallest span yet). */
export function canZoomIn(w: TimeWindow | null, end: number): boolean {
  const r = viewRange(w, end);
  return r.hi > r.lo && (r.hi - r.lo) / 2 >= minSpan(r.hi);
}

/** Half the span, around t (kept at its place on the slider); the window itself when it cannot. */
export function zoomIn(w: TimeWindow | null, t: number, end: number): TimeWindow | null {
  if (!canZoomIn(w, end)) return w;
  const r = viewRange(w, end);
  const x = clamp(t, r.lo, r.hi);
  return { lo: clamp(x - (x - r.lo) / 2, r.lo, r.hi), hi: clamp(x + (r.hi - x) / 2, r.lo, r.hi) };
}

/**
 * Twice the span, around t (kept at its place on the slider), shifted inside [0, end]; the whole
 * history (null) once it would cover it. `end`: where the history ends (timeWindowGuard's historyEnd).
 */
export function zoomOut(w: TimeWindow | null, t: number, end: number): TimeWindow | null {
  if (w === null) return null;
  const x = clamp(t, w.lo, w.hi);
  return fitInside(x - 2 * (x - w.lo), 2 * (w.hi - w.lo), end);
}

/** The window [lo, lo + span] shifted inside [0, end]; null (the whole history) when it does not fit. */
export function fitInside(lo: number, span: number, end: number): TimeWindow | null {
  if (!(span < end)) return null;
  const from = clamp(lo, 0, end - span);
  return { lo: from, hi: Math.min(from + span, end) };
}

/**
 * The window kept around the time t in a history ending at `end` (the same object when it stays):
 * the whole history (null) when the history ends before the window starts; the window itself while
 * it holds t, even when the history now ends inside it (cut by an edit in the past, it is about to be
 * computed again); otherwise the page holding t (see the header), shifted inside [0, end] unless it
 * is the next page forward and the history is `growing` (computed on past its end as time runs).
 */
export function follow(w: TimeWindow | null, t: number, end: number, growing = false): TimeWindow | null {
  if (w === null) return null;
  if (end < w.lo) return null;
  const span = w.hi - w.lo;
  const x = clamp(t, 0, end);
  if (x >= w.lo && x <= w.hi) return w;
  const nextPage = x > w.hi && x <= w.hi + span;
  if (nextPage && growing) return { lo: w.hi, hi: w.hi + span };
  const lo = x > w.hi ? (nextPage ? w.hi : x - span / 2) : x >= w.lo - span ? w.lo - span : x - span / 2;
  return fitInside(lo, span, end);
}

/**
 * The window once the history has stopped growing (timeWindowGuard.ts): a page turned forward into
 * the computation (follow, `growing`) that still reaches past the history's end is shifted back to
 * end there, [end - span, end], so the slider shows no blank stretch; the time t stays (it lies in
 * the window and not past the end, so it stays in the shifted window) and only its place on the
 * slider moves. The whole history (null) when the span does not fit in [0, end]. The same object
 * when the window does not reach past the end, or t is not in it or is held past the end.
 */
export function settle(w: TimeWindow | null, t: number, end: number): TimeWindow | null {
  if (w === null || !(w.hi > end) || t < w.lo || t > end) return w;
  return fitInside(w.lo, w.hi - w.lo, end);
}

/**
 * Significant digits that tell times in the window apart: 6, more when the window is narrow for its
 * times, at most 15. `finer`: the last digit is 10^-finer of the span or less (3: a thousandth, for
 * its ends; 4 for the time, finer than a pixel of the slider).
 */
export function windowDigits(w: TimeWindow, finer = 3): number {
  const span = w.hi - w.lo;
  const size = Math.max(Math.abs(w.lo), Math.abs(w.hi));
  const digits = span > 0 && size > 0 ? Math.ceil(Math.log10(size / span)) + finer : 6;
  return clamp(digits, 6, 15);
}

const written = (x: number, digits: number) => String(Number(x.toPrecision(digits)));

/**
 * The window as the Time panel writes it ("12.5–25"): 6 significant digits, more when the window
 * is narrow for its times, so its two ends always read differently (999999999.5–1000000000.5).
 */
export function windowLabel(w: TimeWindow): string {
  const p = windowDigits(w);
  return `${written(w.lo, p)}–${written(w.hi, p)}`;
}

/**
 * The time t as the Time panel's field writes it while zoomed: to a ten-thousandth of the window
 * (1000000002.346 in a 4 s window around 1e9, where 6 digits read 1e+9 whatever the time);
 * `fallback` (the 6-digit short form) for the whole history.
 */
export function timeInWindow(t: number, w: TimeWindow | null, fallback: (x: number) => string): string {
  if (w === null || Math.abs(t) < 1e-12) return fallback(t);
  return written(t, windowDigits(w, 4));
}
