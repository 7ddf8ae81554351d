/**
 * The Zeno watch: reports a state the exact model cannot pass instead of looping for ever. It is
 * told the time of every counted event (collision or stop), with the World's time before it, and
 * throws a SimulationError when
 *
 * - more than SIMULTANEOUS_EVENTS_PER_BODY * n events (or SIMULTANEOUS_EVENTS_PER_PAIR per pair of
 *   bodies, when that is more) happen at one and the same instant (a resting contact, or a
 *   collapse that friction drives to one instant), or
 * - while energy can be fed in (an immovable body moves), windows of
 *   W = max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY * n) events keep getting shorter (each
 *   lasts at most ZENO_SHRINK times the one before) until one lasts no more than
 *   ZENO_STREAK_PROGRESS times the whole run of shrinking windows before it: events accumulate at
 *   a finite time, as when a disc is crushed between an immovable disc and a wall, or
 * - its push watch (pushWatch.ts) sees one body stop too many times in a row without moving.
 *
 * Only differences of event times are compared, never a time with |t| or a unit: the verdict is the
 * same for the scene shifted in time or run with time × k. (Comparing a window with |t| refused a
 * disc rattling steadily between two walls at t = 1e5, and missed a crush converging on t = 0.)
 *
 * Its counters are part of the simulation's state: a World copied or rebuilt from a keyframe
 * carries them (`save` / `load`, four numbers and the push watch's streaks: the two event counts share one, exactly while
 * n < 2^20, beyond which the counts are capped), so that it throws at exactly the event the
 * original would. The time of the previous event is the World's time before the event, which a
 * copy or a rebuilt World has too.
 */
import {
  SIMULTANEOUS_EVENTS_PER_BODY,
  SIMULTANEOUS_EVENTS_PER_PAIR,
  ZENO_SHRINK,
  ZENO_STREAK_PROGRESS,
  ZENO_WINDOW_EVENTS,
  ZENO_WINDOW_EVENTS_PER_BODY,
} from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { type PushStreaks, PushWatch } from "./pushWatch.js";

const INF = Number.POSITIVE_INFINITY;
/** save() packs the two counts into one number: sameTimeCount + windowCount * COUNT_SPLIT. */
const COUNT_SPLIT = 2 ** 26;

/**
 * The watch's counters: [start of the current window, duration of the window before, start of
 * the run of shrinking windows, events at the current instant + COUNT_SPLIT * events in the window,
 * the push watch's streaks].
 */
export type ZenoCounters = [number, number, number, number, PushStreaks];

/** Events allowed at one instant in a world of n body slots (capped so that save() is exact). */
export function simultaneousLimit(n: number): number {
  const perPair = SIMULTANEOUS_EVENTS_PER_PAIR * ((n * (n - 1)) / 2);
  return Math.min(Math.max(SIMULTANEOUS_EVENTS_PER_BODY * n, Math.floor(perPair)), COUNT_SPLIT - 2);
}

/** Events in one window of the convergence test in a world of n body slots. */
export function zenoWindow(n: number): number {
  return Math.min(Math.max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY * n), 2 ** 26);
}

export class ZenoWatch {
  private sameTimeCount = 0;
  private windowStart = -INF;
  private windowCount = 0;
  private lastProgress = INF;
  private runStart = -INF;
  /** Sustained pushes (told of every stop by the World; edits end a body's streak). */
  readonly push = new PushWatch();

  /**
   * Count an event at `time`, the World's time before it being `before`, in a world of `n` body
   * slots; throw if it reveals a Zeno state. `pumpsEnergy` is asked only at the end of a window that
   * completes a converging run. `what` describes the event, for the message only.
   */
  check(time: number, before: number, n: number, pumpsEnergy: () => boolean, what?: () => string): void {
    // Nothing is counted until the event has passed every test, so the same event, tried again
    // after a throw, throws the same message (as a World rebuilt from the saved counters does).
    const sameTime = time !== before ? 0 : this.sameTimeCount + 1;
    if (sameTime > 0 && sameTime > simultaneousLimit(n)) {
      throw new SimulationError(
        `more than ${sameTime} events at the same instant t=${time}${what === undefined ? "" : ` (the last: ${what()})`}: a Zeno state (resting contact, two discs pressed together, or an inelastic collapse) that the exact model cannot resolve`,
        time,
      );
    }
    const w = zenoWindow(n);
    if (this.windowCount + 1 < w) {
      this.sameTimeCount = sameTime;
      this.windowCount++;
      return;
    }
    const progress = time - this.windowStart;
    // The first window (no start yet) only starts the first run, at its end.
    if (this.windowStart === -INF) this.runStart = time;
    else if (!(progress <= ZENO_SHRINK * this.lastProgress)) this.runStart = this.windowStart;
    else if (progress <= ZENO_STREAK_PROGRESS * (this.windowStart - this.runStart) && pumpsEnergy()) {
      throw new SimulationError(
        `${w} events in ${progress} (to t=${time}), each window of ${w} events shorter than the one before since t=${this.runStart}: events accumulate at a finite time (a Zeno state, e.g. a disc crushed by an immovable body), which the exact model cannot pass`,
        time,
      );
    }
    this.sameTimeCount = sameTime;
    this.lastProgress = progress;
    this.windowStart = time;
    this.windowCount = 0;
  }

  /** The counters, for a copy or a keyframe. */
  save(): ZenoCounters {
    return [
      this.windowStart,
      this.lastProgress,
      this.runStart,
      this.sameTimeCount + COUNT_SPLIT * this.windowCount,
      this.push.save(),
    ];
  }

  /** Restore counters taken by `save`. */
  load(c: Readonly<ZenoCounters>): void {
    [this.windowStart, this.lastProgress, this.runStart] = c;
    this.sameTimeCount = c[3] % COUNT_SPLIT;
    this.windowCount = (c[3] - this.sameTimeCount) / COUNT_SPLIT;
    this.push.load(c[4]);
  }
}
