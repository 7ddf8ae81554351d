/**
 * The Zeno watch: reports a state the exact model cannot pass instead of looping for ever. It is
 * told the time of every counted event (collision or stop), with the World's time before it, and
 * throws a SimulationError when
 *
 * - more than SIMULTANEOUS_EVENTS_PER_BODY * n events (or SIMULTANEOUS_EVENTS_PER_PAIR per pair of
 *   bodies, or SIMULTANEOUS_EVENTS_PER_MASS_SPREAD * n * sqrt(heaviest / lightest finite mass of
 *   the bodies in the events at that instant), whichever is most; at most 2^26 - 2) happen at one
 *   and the same instant (a resting contact, or a collapse that friction drives to one instant);
 *   the allowance for the mass spread holds only while collisions between two different finite
 *   masses keep coming: more than the plain limit of events since the last of them is reported
 *   (a disc jammed between immovable bodies ran to 67 million events when one collision of masses 1
 *   and 1e20 elsewhere had opened the allowance: review), or
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
 * carries them (`save` / `load`, four numbers, the push watch's streaks and the instant's lightest
 * and heaviest finite masses: the two event counts share one, exactly while n < 2^20, beyond which
 * the counts are capped), so that it throws at exactly the event the original would. The time of the previous event is the World's time before the event, which a
 * copy or a rebuilt World has too.
 */
import {
  SIMULTANEOUS_EVENTS_PER_BODY,
  SIMULTANEOUS_EVENTS_PER_MASS_SPREAD,
  SIMULTANEOUS_EVENTS_PER_PAIR,
  ZENO_SHRINK,
  ZENO_STREAK_PROGRESS,
  ZENO_WINDOW_EVENTS,
  ZENO_WINDOW_EVENTS_PER_BODY,
} from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { type PushStreaks, PushWatch } from "./pushWatch.js";
import { convergingReport, culpritIds, sameInstantReport, type ZenoCulprits } from "./zenoAdvice.js";

const INF = Number.POSITIVE_INFINITY;
/** save() packs the two counts into one number: sameTimeCount + windowCount * COUNT_SPLIT. */
const COUNT_SPLIT = 2 ** 26;

/**
 * The watch's counters: [start of the current window, duration of the window before, start of
 * the run of shrinking windows, events at the current instant + COUNT_SPLIT * events in the window,
 * the push watch's streaks, the lightest and the heaviest finite mass in the current instant's
 * events (Infinity and 0 when none), the events at the current instant since the last collision of
 * two different finite masses].
 */
export type ZenoCounters = [number, number, number, number, PushStreaks, number, number, number];

/** Events allowed at one instant in a world of n body slots (capped so that save() is exact). */
export function simultaneousLimit(n: number): number {
  const perPair = SIMULTANEOUS_EVENTS_PER_PAIR * ((n * (n - 1)) / 2);
  return Math.min(Math.max(SIMULTANEOUS_EVENTS_PER_BODY * n, Math.floor(perPair)), COUNT_SPLIT - 2);
}

/** Events allowed at one instant with n body slots and a mass spread (sqrt of the ratio of the
 *  heaviest to the lightest finite mass; see SIMULTANEOUS_EVENTS_PER_MASS_SPREAD). */
export function simultaneousLimitWithSpread(n: number, spread: number): number {
  const bySpread = Math.floor(SIMULTANEOUS_EVENTS_PER_MASS_SPREAD * spread * n);
  return Math.min(Math.max(simultaneousLimit(n), bySpread), COUNT_SPLIT - 2);
}

/** Events in one window of the convergence test in a world of n body slots. */
export function zenoWindow(n: number): number {
  return Math.min(Math.max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY * n), 2 ** 26);
}

export class ZenoWatch {
  private sameTimeCount = 0;
  /** Lightest and heaviest finite mass of the bodies in the events at the current instant. */
  private massLo = INF;
  private massHi = 0;
  /** Events at the current instant since the last collision between two different finite masses. */
  private sinceSpread = 0;
  private windowStart = -INF;
  private windowCount = 0;
  private lastProgress = INF;
  private runStart = -INF;
  /** The body-slot count the two limits below were computed for (-1: none yet). */
  private limitsN = -1;
  /** simultaneousLimit(limitsN) and zenoWindow(limitsN). */
  private plainLimit = 0;
  private windowLimit = 0;
  /** Sustained pushes (told of every stop by the World; edits end a body's streak). */
  readonly push = new PushWatch();

  /** Events counted in the current window (saved with the counters: the trap watch samples by it). */
  get windowEvents(): number {
    return this.windowCount;
  }

  /**
   * Count an event at `time`, the World's time before it being `before`, in a world of `n` body
   * slots, between bodies of masses `ma` and `mb` (Infinity for an obstacle, a stop's second body
   * or an immovable body); throw if it reveals a Zeno state. `pumpsEnergy` is asked only at the end
   * of a window that completes a converging run. `culprits` names who is caught, for the report
   * only (its message and ids: zenoAdvice.ts), given the time since which they have events: the
   * instant, or the start of the last window.
   */
  check(
    time: number,
    before: number,
    n: number,
    pumpsEnergy: () => boolean,
    culprits?: (since: number) => ZenoCulprits,
    ma = INF,
    mb = INF,
  ): void {
    if (n !== this.limitsN) this.setLimits(n);
    if (time !== before && this.windowCount + 1 < this.windowLimit) {
      // The common event, at a new instant inside a window: what the full count below does for it
      // (its instant's counts start again from this event alone; nothing can be refused), small
      // enough for V8 to inline here, so that the times and masses need no boxes (session 29).
      // Masses are positive (validate.ts), so min and max with Infinity for "none" are exact.
      this.massLo = Math.min(ma, mb);
      this.massHi = Math.max(ma < INF ? ma : 0, mb < INF ? mb : 0);
      this.sinceSpread = 0;
      this.sameTimeCount = 0;
      this.windowCount++;
      return;
    }
    this.countEvent(time, before, n, pumpsEnergy, culprits, ma, mb);
  }

  /** The limits for n body slots, computed when n changes (they depend on nothing else). */
  private setLimits(n: number): void {
    this.limitsN = n;
    this.plainLimit = simultaneousLimit(n);
    this.windowLimit = zenoWindow(n);
  }

  /** check's full count, for any event (n's limits set). */
  private countEvent(
    time: number,
    before: number,
    n: number,
    pumpsEnergy: () => boolean,
    culprits: ((since: number) => ZenoCulprits) | undefined,
    ma: number,
    mb: number,
  ): void {
    // Nothing is counted until the event has passed every test, so the same event, tried again
    // after a throw, throws the same message (as a World rebuilt from the saved counters does).
    const sameTime = time !== before ? 0 : this.sameTimeCount + 1;
    let lo = sameTime > 0 ? this.massLo : INF;
    let hi = sameTime > 0 ? this.massHi : 0;
    if (ma < INF) {
      lo = Math.min(lo, ma);
      hi = Math.max(hi, ma);
    }
    if (mb < INF) {
      lo = Math.min(lo, mb);
      hi = Math.max(hi, mb);
    }
    const unequal = ma < INF && mb < INF && ma !== mb;
    const since = sameTime === 0 || unequal ? 0 : this.sinceSpread + 1;
    const plain = this.plainLimit;
    if (
      sameTime > plain &&
      (since > plain || sameTime > simultaneousLimitWithSpread(n, hi > lo ? Math.sqrt(hi / lo) : 1))
    ) {
      const c = culprits?.(time);
      throw new SimulationError(
        sameInstantReport(sameTime, time, c),
        time,
        c === undefined ? [] : culpritIds(c),
      );
    }
    this.massLo = lo;
    this.massHi = hi;
    this.sinceSpread = since;
    const w = this.windowLimit;
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
      const c = culprits?.(this.windowStart);
      throw new SimulationError(
        convergingReport(w, progress, time, this.runStart, c),
        time,
        c === undefined ? [] : culpritIds(c),
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
      this.massLo,
      this.massHi,
      this.sinceSpread,
    ];
  }

  /** Restore counters taken by `save`. */
  load(c: Readonly<ZenoCounters>): void {
    [this.windowStart, this.lastProgress, this.runStart] = c;
    this.sameTimeCount = c[3] % COUNT_SPLIT;
    this.windowCount = (c[3] - this.sameTimeCount) / COUNT_SPLIT;
    this.push.load(c[4]);
    this.massLo = c[5];
    this.massHi = c[6];
    this.sinceSpread = c[7];
  }
}
