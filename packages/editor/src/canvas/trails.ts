/**
 * Trails: the recent positions of each body, recorded from the frames the canvas draws. A jump in
 * time (scrub, step, edit) larger than MAX_GAP_SECONDS clears them, so trails show motion only.
 * A body drawn where it waits for a newer frame (its motion law does not reach the frame's time:
 * canvas/frameAt.ts) is not recorded: that place is not where it is at that time, and recording it
 * drew straight chords across a scrub. A body whose place jumps between two recorded frames (an
 * action put it elsewhere: an edit of its place, at the time shown or played over in either
 * direction, or scrubbed over) starts its trail again there: the motion laws of the two frames, where
 * their intervals meet or overlap, put it in two places (a collision changes the velocity, not the
 * place); when they do not meet (paused frames carry none; several events between two frames), an
 * action between the two frames that may place the body (`bodyActions`) starts it again.
 */
import type { Action } from "../engineTypes";
import {
  F_AX,
  F_AY,
  F_FROM,
  F_UNTIL,
  F_VX,
  F_VY,
  F_X,
  F_Y,
  FRAME_STRIDE,
  type Frame,
} from "../remote/protocol";

/** Whether an action at a time in (lo, hi] may put body `id` elsewhere (a frame at an action's time shows the scene after it). */
export type BodyActed = (id: string, lo: number, hi: number) => boolean;

/** The actions that place a body (add, update, remove: giveVelocity does not), by body id. */
export function bodyActions(actions: readonly Action[]): BodyActed {
  const times = new Map<string, number[]>();
  for (const a of actions) {
    if (a.type !== "addBody" && a.type !== "updateBody" && a.type !== "removeBody") continue;
    const list = times.get(a.id);
    if (list) list.push(a.time);
    else times.set(a.id, [a.time]);
  }
  return (id, lo, hi) => times.get(id)?.some((t) => lo < t && t <= hi) ?? false;
}

export const TRAIL_SAMPLES = 60;
export const MAX_GAP_SECONDS = 0.5;

/** A body's motion law as a frame carried it: the frame's time, then its F_X..F_AY, F_FROM, F_UNTIL. */
type Law = Float64Array;

/** The place (x, y) the law `l` gives at time t. */
function at(l: Law, t: number): [number, number] {
  const dt = t - l[0]!;
  return [l[1]! + dt * (l[3]! + 0.5 * l[5]! * dt), l[2]! + dt * (l[4]! + 0.5 * l[6]! * dt)];
}

/**
 * Whether the body jumped from law a to law b (a recorded first): where their intervals meet or
 * overlap, whether they put it in two places; null when they do not meet (frames drawn paused carry
 * no interval beyond their time; several events between two frames).
 */
function jumped(a: Law, b: Law): boolean | null {
  const lo = Math.max(a[7]!, b[7]!);
  const hi = Math.min(a[8]!, b[8]!);
  if (!(lo <= hi)) return null;
  const t = Math.min(Math.max(b[0]!, lo), hi);
  const [ax, ay] = at(a, t);
  const [bx, by] = at(b, t);
  const tolerance = 1e-9 * (1 + Math.abs(ax) + Math.abs(ay));
  return Math.abs(ax - bx) > tolerance || Math.abs(ay - by) > tolerance;
}

export class TrailRecorder {
  readonly paths = new Map<string, number[]>();
  /** Each body's motion law in the frame that last recorded it. */
  private readonly laws = new Map<string, Law>();
  private readonly scratch: Law = new Float64Array(9);
  /** Time of the last frame that recorded a position. */
  private lastT = Number.NaN;

  /** Records frame f; `acted`: whether an action may have put a body elsewhere (bodyActions). */
  record(f: Frame, acted: BodyActed = () => false): void {
    const d = f.data;
    const n = f.ids.length;
    let atTime = 0;
    for (let i = 0; i < n; i++) {
      const o = i * FRAME_STRIDE;
      if (d[o + F_FROM]! <= f.t && f.t <= d[o + F_UNTIL]!) atTime++;
    }
    if (atTime === 0 && n > 0) return; // every body waits: nothing here is at time f.t
    if (!(Math.abs(f.t - this.lastT) <= MAX_GAP_SECONDS)) {
      this.paths.clear();
      this.laws.clear();
    }
    this.lastT = f.t;
    const seen = new Set<string>();
    for (let i = 0; i < n; i++) {
      const id = f.ids[i]!;
      const o = i * FRAME_STRIDE;
      seen.add(id);
      if (!(d[o + F_FROM]! <= f.t && f.t <= d[o + F_UNTIL]!)) continue;
      const now = this.scratch;
      now[0] = f.t;
      now[1] = d[o + F_X]!;
      now[2] = d[o + F_Y]!;
      now[3] = d[o + F_VX]!;
      now[4] = d[o + F_VY]!;
      now[5] = d[o + F_AX]!;
      now[6] = d[o + F_AY]!;
      now[7] = d[o + F_FROM]!;
      now[8] = d[o + F_UNTIL]!;
      const law = this.laws.get(id);
      let p = this.paths.get(id);
      if (!p || (law && (jumped(law, now) ?? acted(id, Math.min(law[0]!, f.t), Math.max(law[0]!, f.t))))) {
        p = [];
        this.paths.set(id, p);
      }
      if (law) law.set(now);
      else this.laws.set(id, now.slice());
      p.push(d[o + F_X]!, d[o + F_Y]!);
      if (p.length > 2 * TRAIL_SAMPLES) p.splice(0, p.length - 2 * TRAIL_SAMPLES);
    }
    for (const id of this.paths.keys()) if (!seen.has(id)) this.paths.delete(id);
    for (const id of this.laws.keys()) if (!seen.has(id)) this.laws.delete(id);
  }
}
