/**
 * Trails: the recent positions of each body, recorded from the frames the canvas draws. A jump in
 * time (scrub, step, edit) larger than MAX_GAP_SECONDS clears them, so trails show motion only.
 * A body drawn where it waits for a newer frame (its motion law does not reach the frame's time:
 * canvas/frameAt.ts) is not recorded: that place is not where it is at that time, and recording it
 * drew straight chords across a scrub.
 */
import { F_FROM, F_UNTIL, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";

export const TRAIL_SAMPLES = 60;
export const MAX_GAP_SECONDS = 0.5;

export class TrailRecorder {
  readonly paths = new Map<string, number[]>();
  /** Time of the last frame that recorded a position. */
  private lastT = Number.NaN;

  record(f: Frame): void {
    const d = f.data;
    const n = f.ids.length;
    let atTime = 0;
    for (let i = 0; i < n; i++) {
      const o = i * FRAME_STRIDE;
      if (d[o + F_FROM]! <= f.t && f.t <= d[o + F_UNTIL]!) atTime++;
    }
    if (atTime === 0 && n > 0) return; // every body waits: nothing here is at time f.t
    if (!(Math.abs(f.t - this.lastT) <= MAX_GAP_SECONDS)) this.paths.clear();
    this.lastT = f.t;
    const seen = new Set<string>();
    for (let i = 0; i < n; i++) {
      const id = f.ids[i]!;
      const o = i * FRAME_STRIDE;
      seen.add(id);
      if (!(d[o + F_FROM]! <= f.t && f.t <= d[o + F_UNTIL]!)) continue;
      let p = this.paths.get(id);
      if (!p) {
        p = [];
        this.paths.set(id, p);
      }
      p.push(d[o + F_X]!, d[o + F_Y]!);
      if (p.length > 2 * TRAIL_SAMPLES) p.splice(0, p.length - 2 * TRAIL_SAMPLES);
    }
    for (const id of this.paths.keys()) if (!seen.has(id)) this.paths.delete(id);
  }
}
