/**
 * The Time slider's arrow and page keys while zoomed (TimeSlider): the time they move to, also past
 * the window's edges. A range input stops its keys at its min and max, which while zoomed are the
 * window's edges, so a keyboard user could not get past them; the slider handles them itself
 * instead: ←/↓ and →/↑ move the time by a hundredth of the window's span and Page Down / Page Up by a
 * tenth (Chromium's steps for step="any"), kept within [0, end] (end: where the history ends), and a
 * time past an edge turns the window's page (timeWindowGuard.ts) as playback does. Home and End are
 * left to the input (the start and end of the window shown), as is every key of the whole history
 * (its ends are the history's). Pure function.
 */
import type { TimeWindow } from "../store/timeWindow";

/** The fraction of the window's span an arrow key moves the time by. */
export const ARROW_STEP = 1 / 100;
/** The fraction of the window's span Page Up / Page Down move the time by. */
export const PAGE_STEP = 1 / 10;

const STEPS: Record<string, number> = {
  ArrowRight: ARROW_STEP,
  ArrowUp: ARROW_STEP,
  ArrowLeft: -ARROW_STEP,
  ArrowDown: -ARROW_STEP,
  PageUp: PAGE_STEP,
  PageDown: -PAGE_STEP,
};

/**
 * The time a key on the slider moves t to while the slider shows the window `w` of a history ending
 * at `end`; null when the key is left to the input (not zoomed, or not an arrow or page key).
 * The move starts from the thumb's place (t within the window) and stays within [0, end].
 */
export function sliderKeyTime(key: string, t: number, w: TimeWindow | null, end: number): number | null {
  const step = STEPS[key];
  if (w === null || step === undefined) return null;
  const from = Math.min(Math.max(t, w.lo), w.hi);
  return Math.min(Math.max(from + step * (w.hi - w.lo), 0), Math.max(end, 0));
}
