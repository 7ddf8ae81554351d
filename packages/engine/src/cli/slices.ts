/**
 * The CLI's computation in slices, and how it is stopped (pure: no process access).
 * computeSlices(tl, until, progress, clock) is a generator: each step computes one slice
 * (Timeline.prolongSlice toward `until`, counted from the horizon at the first slice), reports
 * progress after it when the progress's cadence says a line is due, and yields unless the run is
 * done; it returns why the run ended. A slice is SLICE_EVENTS collisions and stops; given a clock
 * (the bin's performance.now, read once at the start and once after each slice), the first is
 * FIRST_SLICE_EVENTS and each next one sized to last about SLICE_TARGET_MS (cadence.ts), and the
 * cadence is told the time elapsed. Slicing changes nothing in the history (the Timeline's
 * contract), so the result is the one a single prolong gives, whatever the clock says.
 * A driver runs such a generator (the whole command is one: run.ts): runToEnd runs it through
 * without pausing; runInterruptible pauses between steps (`pause`, the bin's setImmediate, lets a
 * signal handler run) and, once `interrupted()` names a signal, throws an Interrupted into the
 * generator at the yield where it stands, so the command can print what it computed so far.
 */
import type { Until } from "../scene/types.js";
import type { ProlongResult } from "../timeline/types.js";
import { type Cadence, FIRST_SLICE_EVENTS, nextSliceBudget, SLICE_EVENTS } from "./cadence.js";

export { SLICE_EVENTS };

/** The signals that interrupt a run, and the exit status of a run each interrupted (128 + number). */
export const INTERRUPT_STATUS = { SIGINT: 130, SIGTERM: 143 } as const;
export type InterruptSignal = keyof typeof INTERRUPT_STATUS;

/** Thrown into a command's generator when a signal interrupts it. */
export class Interrupted extends Error {
  readonly signal: InterruptSignal;
  constructor(signal: InterruptSignal) {
    super(`interrupted by ${signal}`);
    this.name = "Interrupted";
    this.signal = signal;
  }
  /** The exit status of the interrupted run: 130 (SIGINT), 143 (SIGTERM). */
  get status(): number {
    return INTERRUPT_STATUS[this.signal];
  }
}

/** What computeSlices needs of a Timeline. */
export interface Sliceable {
  prolongSlice(
    until: Until,
    budget: number,
  ): { done: boolean; events: number; horizon: number; reason?: ProlongResult["reason"] };
}

/** Progress reports: after a slice that does not finish the run when `due` says so (a Cadence), and
 *  once when the run ends (done, failed or interrupted) after a report was made. */
export interface Progress extends Cadence {
  report(horizon: number, events: number): void;
  end(): void;
}

/** Computes `until` in slices, yielding between them; returns why the run ended (see the header). */
export function* computeSlices(
  tl: Sliceable,
  until: Until,
  progress: Progress | null,
  clock?: () => number,
): Generator<void, ProlongResult["reason"], void> {
  let total = 0;
  let reported = false;
  const start = clock === undefined ? Number.NaN : clock();
  let budget = clock === undefined ? SLICE_EVENTS : FIRST_SLICE_EVENTS;
  let last = start;
  try {
    for (;;) {
      const r = tl.prolongSlice(until, budget);
      total += r.events;
      if (r.done) return r.reason ?? "idle";
      let now = Number.NaN;
      if (clock !== undefined) {
        now = clock();
        budget = nextSliceBudget(budget, now - last);
        last = now;
      }
      if (progress?.due(total, now - start)) {
        progress.report(r.horizon, total);
        reported = true;
      }
      yield;
    }
  } finally {
    if (reported) progress?.end();
  }
}

/** Runs a command's generator through without pausing (nothing can interrupt it). */
export function runToEnd<T>(steps: Generator<void, T, void>): T {
  for (;;) {
    const r = steps.next();
    if (r.done) return r.value;
  }
}

/** How runInterruptible pauses between steps and learns of an interrupt. */
export interface InterruptControl {
  /** Resolves once other work may have run (the bin: setImmediate, so signal handlers run). */
  pause(): Promise<void>;
  /** A signal received since the last call, or null: each signal is reported once (a second one
   *  while the result is written stops it: writing.ts). */
  interrupted(): InterruptSignal | null;
}

/** Runs a command's generator, pausing between steps; an interrupt is thrown into it as Interrupted
 *  (it may catch it and return, or let it propagate: then this rejects with it). */
export async function runInterruptible<T>(
  steps: Generator<void, T, void>,
  control: InterruptControl,
): Promise<T> {
  let r = steps.next();
  while (!r.done) {
    await control.pause();
    const signal = control.interrupted();
    r = signal === null ? steps.next() : steps.throw(new Interrupted(signal));
  }
  return r.value;
}
