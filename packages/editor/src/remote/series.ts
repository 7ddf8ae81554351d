/**
 * Energy and event count over time, recorded at the horizon as the timeline is computed (the host
 * records at most every RECORD_EVERY_MS of computing, so the readings cost little). A cut in the past drops
 * the samples after the new horizon; the list is thinned by half when it grows past MAX_SAMPLES.
 */
import type { SeriesPoint } from "./protocol";
import type { TimelineLike } from "./timelineLike";

export const MAX_SAMPLES = 4096;

export class SeriesRecorder {
  private samples: SeriesPoint[] = [];

  clear(): void {
    this.samples = [];
  }

  /** Forgets the samples after time t (an edit at t changes everything after it). */
  cut(t: number): void {
    while (this.samples.length > 0 && this.samples[this.samples.length - 1]!.t > t) this.samples.pop();
  }

  record(tl: Pick<TimelineLike, "horizon" | "eventCount" | "stateAt">): void {
    const t = tl.horizon;
    while (this.samples.length > 0 && this.samples[this.samples.length - 1]!.t > t) this.samples.pop();
    const last = this.samples[this.samples.length - 1];
    if (last && last.t === t && last.collisions === tl.eventCount) return;
    let energy = 0;
    for (const b of tl.stateAt(t).bodies)
      if (Number.isFinite(b.m)) energy += 0.5 * b.m * (b.vx * b.vx + b.vy * b.vy);
    if (last && last.t === t) this.samples.pop();
    this.samples.push({ t, energy, collisions: tl.eventCount });
    if (this.samples.length > MAX_SAMPLES) this.samples = this.samples.filter((_, i) => i % 2 === 0);
  }

  /** At most n samples spread over the recorded ones (always including the last). */
  points(n: number): SeriesPoint[] {
    const s = this.samples;
    if (s.length <= n) return s.slice();
    const out: SeriesPoint[] = [];
    for (let k = 0; k < n; k++) out.push(s[Math.round((k * (s.length - 1)) / (n - 1))]!);
    return out;
  }
}

/** Logs up to this many events get an exact series (one log read + stateAt per sample). */
export const EXACT_MAX_EVENTS = 20_000;
/** ... and up to this many bodies (stateAt costs per body). */
export const EXACT_MAX_BODIES = 300;

/**
 * The exact series of a small timeline: energy at n + 1 evenly spaced times, and the number of
 * logged events up to each of them (counted from one read of the whole log).
 */
export function exactSeries(
  tl: Pick<TimelineLike, "horizon" | "stateAt" | "eventsBetween">,
  n: number,
): SeriesPoint[] {
  const h = tl.horizon;
  const times = tl.eventsBetween(0, h).map((e) => e.time);
  const out: SeriesPoint[] = [];
  let k = 0;
  for (let i = 0; i <= n; i++) {
    const t = i === n ? h : (h * i) / n;
    while (k < times.length && times[k]! <= t) k++;
    let energy = 0;
    for (const b of tl.stateAt(t).bodies)
      if (Number.isFinite(b.m)) energy += 0.5 * b.m * (b.vx * b.vx + b.vy * b.vy);
    out.push({ t, energy, collisions: k });
  }
  return out;
}
