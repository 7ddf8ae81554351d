/**
 * When the CLI shows a progress line (pure: the clock is given, never read here). The computation
 * (slices.ts) asks `due(events)` after each slice that does not finish the run; a true answer makes
 * it show a line.
 * - clockCadence(now): on a wall clock. The first line once FIRST_REPORT_MS have passed since the
 *   cadence was made (the computation's start: a run that ends sooner shows none), then one each
 *   time REPORT_EVERY_MS have passed since the last line, however many events that is (a slow scene
 *   still shows one about every second, a fast one no more often). A slice that runs past several
 *   periods gives one line, not a burst. `now` is the bin's monotonic clock (performance.now, in
 *   milliseconds); the engine's own code reads no clock (test/exactArithmetic.test.ts), and the
 *   results do not depend on it: only when lines are written does.
 * - eventCadence(): every PROGRESS_EVERY_EVENTS events, for a caller that gives no clock (runCli in
 *   process): deterministic lines.
 * A line can only come between two slices, so a slice longer than the period delays it.
 */

/** Milliseconds from the start of the computation to its first progress line. */
export const FIRST_REPORT_MS = 500;
/** Milliseconds between two progress lines. */
export const REPORT_EVERY_MS = 1000;
/** Events between two progress lines when no clock is given (a multiple of SLICE_EVENTS). */
export const PROGRESS_EVERY_EVENTS = 200_000;

/** Decides, after each slice, whether a progress line is due (see the header). */
export interface Cadence {
  /** Whether to show a line now, `events` events into the computation. */
  due(events: number): boolean;
}

/** A line FIRST_REPORT_MS after now(), then every REPORT_EVERY_MS (see the header). */
export function clockCadence(now: () => number): Cadence {
  let next = now() + FIRST_REPORT_MS;
  return {
    due: () => {
      const t = now();
      if (!(t >= next)) return false;
      next = t + REPORT_EVERY_MS;
      return true;
    },
  };
}

/** A line each time the events reach the next multiple of PROGRESS_EVERY_EVENTS. */
export function eventCadence(): Cadence {
  let next = PROGRESS_EVERY_EVENTS;
  return {
    due: (events) => {
      if (events < next) return false;
      // a slice that is not done computes its whole budget, but do not rely on it for progress
      while (next <= events) next += PROGRESS_EVERY_EVENTS;
      return true;
    },
  };
}
