/**
 * What an interrupt (SIGINT, SIGTERM) does while the CLI writes its result. The writers yield
 * between pieces of the output (output.ts: resultSteps, pathSteps) and the bin keeps its signal
 * handlers installed until it ends, so an interrupt is seen at the next piece (runInterruptible
 * throws it there as Interrupted; finishWriting catches it).
 * The first interrupt of a run is the one that asks to stop. During the computation it stops the
 * computation, and the result so far is written (run.ts). During the writing, the result is
 * finished, so that what the user gets is whole, valid JSON, and a line on stderr says so and how to
 * stop at once: a demanding user loses neither the run's work nor the parseability of its output.
 * An interrupt after that first one stops the writing at once (WritingAborted): the output is then
 * incomplete, not valid JSON, and a line on stderr says so. The exit status of an interrupted run is
 * the signal's (130, 143) either way, so a script learns that the run was interrupted.
 */
import { INTERRUPT_STATUS, Interrupted, type InterruptSignal } from "./slices.js";

/** Thrown by finishWriting at a second interrupt: the output was left incomplete. */
export class WritingAborted extends Error {
  readonly signal: InterruptSignal;
  constructor(signal: InterruptSignal) {
    super(
      `interrupted again by ${signal} while the result was being written: stopped at once, so the output is incomplete (not valid JSON)`,
    );
    this.name = "WritingAborted";
    this.signal = signal;
  }
  /** The exit status: 130 (SIGINT), 143 (SIGTERM). */
  get status(): number {
    return INTERRUPT_STATUS[this.signal];
  }
}

/**
 * Runs the writer `steps` to its end, yielding where it yields (see the header). `earlier` is the
 * interrupt that already stopped the computation, if one did. The first interrupt is told to
 * `notice` (one line, without "chapgame: ") and the writing goes on; one after it throws
 * WritingAborted. Returns the run's interrupt (`earlier` or the one received while writing), or null.
 */
export function* finishWriting(
  steps: Generator<void, void, void>,
  earlier: InterruptSignal | null,
  notice: (line: string) => void,
): Generator<void, InterruptSignal | null, void> {
  let received = earlier;
  for (let r = steps.next(); !r.done; r = steps.next()) {
    try {
      yield;
    } catch (e) {
      if (!(e instanceof Interrupted)) throw e;
      if (received !== null) throw new WritingAborted(e.signal);
      received = e.signal;
      notice(
        `${e.signal} while the result is being written: finishing it, so that it is whole (interrupt again, e.g. Ctrl-C, to stop at once, leaving it incomplete)`,
      );
    }
  }
  return received;
}

/** The exit status of a run that would end with `status`: an interrupt's when one came while its
 *  result was written and the run had otherwise succeeded (an error's status says more). */
export function statusAfterWriting(status: number, received: InterruptSignal | null): number {
  return status === 0 && received !== null ? INTERRUPT_STATUS[received] : status;
}
