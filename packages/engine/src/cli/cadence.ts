/**
 * The pace of the CLI's computation on a wall clock (pure: given the elapsed time, never reading a
 * clock; slices.ts reads the bin's clock, performance.now, between two slices). Only when progress
 * lines are written and where the computation pauses depend on it, never a result: slicing changes
 * nothing in the history (the Timeline's contract), and the engine's own code reads no clock
 * (test/exactArithmetic.test.ts).
 * - A Cadence says after each slice that does not finish the run whether a progress line is due.
 *   clockCadence(): the first line once FIRST_REPORT_MS have passed since the computation started (a
 *   run that ends sooner shows none), then one each time REPORT_EVERY_MS have passed since the last
 *   line, however many events that is (a slow scene still shows one about every second, a fast one
 *   no more often); a slice that ran past several periods gives one line, not a burst.
 *   eventCadence(): every PROGRESS_EVERY_EVENTS events, for a caller that gives no clock (runCli in
 *   process): deterministic lines.
 * - nextSliceBudget(): the events of the next slice, so that a slice lasts about SLICE_TARGET_MS
 *   whatever the scene's cost per event: at most SLICE_EVENTS (a few ms to tens of ms on most
 *   scenes), fewer on a slow one (2,000 long segments crossing a box: 6 s for 10,000 events), so
 *   that a line or an interrupt never waits long for the slice to end.
 */
/** Collisions and stops computed between two chances to stop, at most (a few ms to tens of ms on
 *  most scenes; the only size without a clock). */
export const SLICE_EVENTS = 10_000;
/** Milliseconds from the start of the computation to its first progress line. */
export const FIRST_REPORT_MS = 500;
/** Milliseconds between two progress lines. */
export const REPORT_EVERY_MS = 1000;
/** Events between two progress lines when no clock is given (a multiple of SLICE_EVENTS). */
export const PROGRESS_EVERY_EVENTS = 200_000;
/** Milliseconds a slice should last on the clock (a line or an interrupt waits at most about that). */
export const SLICE_TARGET_MS = 100;
/** Events of the first slice on the clock: a slow scene's first slice ends soon too. */
export const FIRST_SLICE_EVENTS = 1_000;

/** Decides, after each slice, whether a progress line is due (see the header). */
export interface Cadence {
  /** Whether to show a line now, `events` events and `elapsed` ms into the computation (NaN: no
   *  clock). */
  due(events: number, elapsed: number): boolean;
}

/** A line FIRST_REPORT_MS into the computation, then every REPORT_EVERY_MS (see the header). */
export function clockCadence(): Cadence {
  let next = FIRST_REPORT_MS;
  return {
    due: (_events, elapsed) => {
      if (!(elapsed >= next)) return false;
      next = elapsed + REPORT_EVERY_MS;
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

/**
 * The budget of the slice after one of `budget` events that lasted `ms`: scaled down to last about
 * SLICE_TARGET_MS when it lasted longer (at least 1 event), doubled back up to SLICE_EVENTS when it
 * lasted less than half of that, else kept. A time that is not a number keeps the budget.
 */
export function nextSliceBudget(budget: number, ms: number): number {
  if (ms > SLICE_TARGET_MS) return Math.max(1, Math.floor((budget * SLICE_TARGET_MS) / ms));
  if (ms < SLICE_TARGET_MS / 2) return Math.min(SLICE_EVENTS, budget * 2);
  return budget;
}
