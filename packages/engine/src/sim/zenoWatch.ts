/**
 * The Zeno watch: reports a state the exact model cannot pass instead of looping for ever. It is
 * told the time of every counted event (collision or stop) and throws a SimulationError when
 *
 * - more than SIMULTANEOUS_EVENTS_PER_BODY * n events happen at one and the same instant (a
 *   resting contact or an inelastic collapse), or
 * - a window of max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY * n) events advances time by
 *   no more than ZENO_MIN_PROGRESS relative to |t|, while energy can be fed in (an immovable body
 *   moves): a disc crushed between an immovable disc and a wall collides infinitely often before
 *   the crush, at distinct instants. Relative to |t| alone, with no unit of time, so that a scene
 *   run with time × k (and its start time × k) is reported at the same event: with max(1, |t|), a
 *   disc bouncing between two walls 1e-12 s apart beside a moving immovable disc was taken for a
 *   Zeno state (test/scale.prop.test.ts).
 *
 * Its four counters are part of the simulation's state: a World copied or rebuilt from a keyframe
 * carries them (`save` / `load`), so that it throws at exactly the event the original would.
 */
import {
  SIMULTANEOUS_EVENTS_PER_BODY,
  ZENO_MIN_PROGRESS,
  ZENO_WINDOW_EVENTS,
  ZENO_WINDOW_EVENTS_PER_BODY,
} from "../tolerances.js";
import { SimulationError } from "./errors.js";

const INF = Number.POSITIVE_INFINITY;

/** The watch's counters: [time of the current run of simultaneous events, its length, window start, window length]. */
export type ZenoCounters = [number, number, number, number];

export class ZenoWatch {
  private sameTime = -INF;
  private sameTimeCount = 0;
  private windowStart = -INF;
  private windowCount = 0;

  /**
   * Count an event at `time` in a world of `n` body slots; throw if it reveals a Zeno state.
   * `pumpsEnergy` is asked only at the end of a window that made too little progress.
   */
  check(time: number, n: number, pumpsEnergy: () => boolean): void {
    if (time !== this.sameTime) {
      this.sameTime = time;
      this.sameTimeCount = 0;
    } else if (++this.sameTimeCount > SIMULTANEOUS_EVENTS_PER_BODY * n) {
      throw new SimulationError(
        `more than ${this.sameTimeCount} events at the same instant t=${time}: a Zeno state (resting contact or an inelastic collapse) that the exact model cannot resolve`,
        time,
      );
    }
    if (++this.windowCount < Math.max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY * n)) return;
    const progress = time - this.windowStart;
    if (progress <= ZENO_MIN_PROGRESS * Math.abs(time) && pumpsEnergy()) {
      throw new SimulationError(
        `${this.windowCount} events while time advanced only ${progress} (to t=${time}): events accumulate at a finite time (a Zeno state, e.g. a disc crushed by an immovable body), which the exact model cannot pass`,
        time,
      );
    }
    this.windowStart = time;
    this.windowCount = 0;
  }

  /** The counters, for a copy or a keyframe. */
  save(): ZenoCounters {
    return [this.sameTime, this.sameTimeCount, this.windowStart, this.windowCount];
  }

  /** Restore counters taken by `save`. */
  load(c: readonly [number, number, number, number]): void {
    [this.sameTime, this.sameTimeCount, this.windowStart, this.windowCount] = c;
  }
}
