/**
 * The push watch: reports a sustained push instead of computing it for ever. A disc pushed along
 * against friction by another is, in this model (elastic impulses, sliding friction), kicked by
 * rounding-size impulses and stopped by friction again before it moves a bit: in the break of a
 * 30 x 30 rack, three events per 8e-14 s for a push of ~0.075 s (~1e12 events), whose times do not
 * converge, so the Zeno watch's windows miss it.
 *
 * It is told every stop: the body's id and whether it stopped exactly where its motion started (a
 * micro-stop). It keeps the streaks of consecutive micro-stops of up to ZENO_PUSH_BODIES bodies; a
 * stop that moved the body ends its streak, and so does an edit of the body (`forget`). A streak
 * longer than ZENO_PUSH_STREAK throws a SimulationError naming the body and what to do (zenoAdvice.ts). Ordinary scenes have
 * micro-stops too (a ball nudged by a rounding-size impulse in a break: 6 of 47 events), but not
 * 100,000 of one ball without it moving or being edited in between.
 *
 * Its streaks are part of the simulation's state, saved and restored with the Zeno watch's counters
 * (ZenoCounters), so that a World rebuilt from a keyframe throws at the same event.
 */
import { ZENO_PUSH_BODIES, ZENO_PUSH_STREAK } from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { pushReport } from "./zenoAdvice.js";

/** Streaks as saved: [body id, consecutive micro-stops] per watched body. */
export type PushStreaks = readonly (readonly [string, number])[];

export class PushWatch {
  private ids: string[] = [];
  private counts: number[] = [];

  /**
   * Throw if counting the stop of body `id` at `time` would reveal a sustained push; count nothing
   * (so that the same stop, tried again after the throw, throws the same message).
   */
  check(id: string, unmoved: boolean, time: number): void {
    if (!unmoved) return;
    const k = this.ids.indexOf(id);
    const n = k >= 0 ? (this.counts[k] as number) + 1 : 1;
    if (n > ZENO_PUSH_STREAK) throw new SimulationError(pushReport(id, n, time), time, [id]);
  }

  /** Count the stop of body `id` at `time`; `unmoved`: it stopped where its motion started. */
  stop(id: string, unmoved: boolean, time: number): void {
    this.check(id, unmoved, time);
    const k = this.ids.indexOf(id);
    if (!unmoved) {
      if (k >= 0) this.drop(k);
      return;
    }
    if (k >= 0) {
      this.counts[k] = (this.counts[k] as number) + 1;
      return;
    }
    if (this.ids.length < ZENO_PUSH_BODIES) {
      this.ids.push(id);
      this.counts.push(1);
      return;
    }
    // Full: the shortest streak gives way (the first of equals, so the choice is deterministic).
    let least = 0;
    for (let j = 1; j < this.counts.length; j++)
      if ((this.counts[j] as number) < (this.counts[least] as number)) least = j;
    this.ids[least] = id;
    this.counts[least] = 1;
  }

  /** The body was edited (or removed): its streak ends. */
  forget(id: string): void {
    const k = this.ids.indexOf(id);
    if (k >= 0) this.drop(k);
  }

  /** Every streak ends (a change of the fields). */
  clear(): void {
    this.ids = [];
    this.counts = [];
  }

  save(): PushStreaks {
    return this.ids.map((id, k) => [id, this.counts[k] as number] as const);
  }

  load(s: PushStreaks): void {
    this.ids = s.map(([id]) => id);
    this.counts = s.map(([, n]) => n);
  }

  private drop(k: number): void {
    this.ids.splice(k, 1);
    this.counts.splice(k, 1);
  }
}
