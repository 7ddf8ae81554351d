/**
 * The last instant of a Timeline without history (history: false), so that an action applied at
 * the horizon still joins the group of actions applied there, as building from scratch does.
 *
 * With history, an action at the horizon after events that the instant's own actions caused (a
 * push that starts a collision at once) restores the keyframe taken after the instant's actions
 * and applies the group again with it. Without history there is no keyframe: the Timeline keeps
 * instead the undo of its first apply at that instant (saveCore: the core as it was before it) and
 * the actions applied there since. `reapplyInstant` goes back to that point and applies all of them
 * and the new one as one group, then computes as apply does; the result is the one a Timeline with
 * history (or one built from scratch) gives. On an error the instant is left as it was computed.
 * The record is valid while the core is the same object and the horizon is still that instant
 * (setActions makes a new core or restores; computing past the instant drops it).
 */
import type { Action } from "../scene/types.js";
import type { TimelineCore } from "./core.js";
import { goalFrom } from "./goals.js";
import { saveCore } from "./undo.js";

const INF = Number.POSITIVE_INFINITY;

/** What a Timeline without history keeps of its last instant (see the header). */
export interface HeadlessInstant {
  /** the core this was recorded on (a new core, from setActions, makes it stale) */
  core: TimelineCore;
  /** the instant */
  time: number;
  /** takes the core back to before the first action applied at `time` */
  undo: () => void;
  /** the actions applied (by apply) at `time` since that point, in order */
  actions: Action[];
}

/** Whether `inst` still describes the core's horizon instant. */
export function instantHolds(
  inst: HeadlessInstant | null,
  c: TimelineCore,
  t: number,
): inst is HeadlessInstant {
  return inst !== null && inst.core === c && inst.time === t && c.horizon === t;
}

/**
 * Records a successful forward apply of `a` without history, whose undo is `undo`: a new instant,
 * or one more action of the current one. Returns the record to keep.
 */
export function noteInstant(
  inst: HeadlessInstant | null,
  c: TimelineCore,
  a: Action,
  undo: () => void,
): HeadlessInstant | null {
  if (c.history) return null;
  if (inst !== null && inst.core === c && inst.time === a.time) {
    inst.actions.push(a);
    return inst;
  }
  return { core: c, time: a.time, undo, actions: [a] };
}

/**
 * Applies `a` at the instant `inst` describes (instantHolds) together with the actions applied there
 * before it, as one group (see the header). Throws what apply would (the core then unchanged).
 */
export function reapplyInstant(c: TimelineCore, inst: HeadlessInstant, a: Action): void {
  const back = saveCore(c, c.records.length); // this instant as computed, if the group is refused
  try {
    inst.undo();
    // the undo's saved objects are now the core's own: a fresh copy for the next action here
    inst.undo = saveCore(c, c.records.length);
    const group = [...inst.actions, a];
    let index = 0;
    for (const b of group) {
      let at = c.acts.length;
      while (at > 0 && (c.acts[at - 1] as Action).time > b.time) at--;
      c.acts.splice(at, 0, b);
      index = at;
    }
    // the new action is the last inserted; the others by their index in `actions` without it
    c.pathOf = (i) => (i === index ? "action" : `actions[${i > index ? i - 1 : i}]`);
    c.drive(INF, { tLimit: a.time, eLimit: INF });
    if (!c.untils) for (const b of group) if (b.until) c.goals.push(goalFrom(c, b.until, b.time));
    c.drive(INF, null);
    c.pathOf = (i) => `actions[${i}]`;
  } catch (e) {
    back();
    throw e;
  }
  inst.actions.push(a);
}
