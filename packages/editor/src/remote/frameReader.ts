/**
 * FrameReader: the host's frames (protocol.ts) read from the Timeline without an object per body.
 * The bodies come from bodyArraysAt, written into the arrays of the previous read (the timeline
 * also goes on from that read's replay when the time moves forwards: playback). The rest of a frame
 * (g, gravity, lines, points) is kept from the last stateAt, read again only when it may differ.
 * Only actions change it, so it is the same at every time with the same actions applied: the same
 * timeline object, the same action list (by its actions' identity), the same number of actions at
 * or before t, and, at the horizon, the same number of log entries (the horizon's instant may be
 * partly computed: its actions logged by a later slice). A frame is what packFrame(stateAt(t))
 * gives, bit for bit; as there, its ids are the previous frame's array when the ids are unchanged.
 */
import type { Action, BodyArrays } from "../engineTypes";
import { type FrameStatics, packArrays, packFrame } from "./packFrame";
import type { Frame } from "./protocol";
import type { TimelineLike } from "./timelineLike";

/** What the statics of a frame depend on (see the header). */
interface StaticsKey {
  tl: TimelineLike;
  actions: readonly Action[];
  /** Actions at or before the frame's time. */
  applied: number;
  /** At the horizon: the timeline's log entries then; before it: -1. */
  entriesAtHorizon: number;
}

/** Number of actions with time <= t (`actions` are in time order). */
function appliedBy(actions: readonly Action[], t: number): number {
  let lo = 0;
  let hi = actions.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (actions[mid]!.time <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** Whether two lists hold the same objects in the same order. */
function sameItems<T>(a: readonly T[], b: readonly T[]): boolean {
  if (a === b) return true;
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

export class FrameReader {
  private arrays: BodyArrays | undefined = undefined;
  private statics: { key: StaticsKey; value: FrameStatics } | null = null;
  /** The engine's ids array the last frame from `arrays` was packed from, and that frame's ids. */
  private engineIds: readonly string[] | null = null;
  private frameIds: string[] | null = null;

  /** The frame at time t (a time stateAt accepts). `previousIds`: the ids of the last frame sent. */
  frame(tl: TimelineLike, t: number, revision: number, previousIds: string[] | null): Frame {
    const actions = tl.actions;
    const key: StaticsKey = {
      tl,
      actions,
      applied: appliedBy(actions, t),
      entriesAtHorizon: t >= tl.horizon ? tl.eventCount : -1,
    };
    const kept = this.statics;
    if (
      kept === null ||
      kept.key.tl !== tl ||
      kept.key.applied !== key.applied ||
      kept.key.entriesAtHorizon !== key.entriesAtHorizon ||
      !sameItems(kept.key.actions, actions)
    ) {
      const s = tl.stateAt(t);
      this.statics = { key, value: { g: s.g, gravity: s.gravity, lines: s.lines, points: s.points } };
      return packFrame(s, revision, previousIds);
    }
    kept.key.actions = actions; // the same actions: the next comparison is by reference
    const a = tl.bodyArraysAt(t, this.arrays);
    this.arrays = a;
    const same =
      previousIds !== null &&
      ((a.ids === this.engineIds && previousIds === this.frameIds) || sameItems(a.ids, previousIds));
    const ids = same ? previousIds : [...a.ids];
    this.engineIds = a.ids;
    this.frameIds = ids;
    return packArrays(a, kept.value, revision, ids);
  }
}
