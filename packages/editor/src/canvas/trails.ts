/**
 * Trails: the recent positions of each body, recorded from the frames the canvas draws. A jump in
 * time (scrub, step, edit) larger than MAX_GAP_SECONDS clears them, so trails show motion only.
 */
import { F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";

export const TRAIL_SAMPLES = 60;
export const MAX_GAP_SECONDS = 0.5;

export class TrailRecorder {
  readonly paths = new Map<string, number[]>();
  private lastT = Number.NaN;

  record(f: Frame): void {
    if (!(Math.abs(f.t - this.lastT) <= MAX_GAP_SECONDS)) this.paths.clear();
    this.lastT = f.t;
    const seen = new Set<string>();
    for (let i = 0; i < f.ids.length; i++) {
      const id = f.ids[i]!;
      seen.add(id);
      let p = this.paths.get(id);
      if (!p) {
        p = [];
        this.paths.set(id, p);
      }
      p.push(f.data[i * FRAME_STRIDE + F_X]!, f.data[i * FRAME_STRIDE + F_Y]!);
      if (p.length > 2 * TRAIL_SAMPLES) p.splice(0, p.length - 2 * TRAIL_SAMPLES);
    }
    for (const id of this.paths.keys()) if (!seen.has(id)) this.paths.delete(id);
  }
}
