/**
 * Goals of a TimelineCore: how far to compute. A goal is met at `tLimit` (every event at that time
 * processed) or after `eLimit` collisions and stops in total, whichever first, or when nothing is
 * left to happen. goalFrom turns an action's or a prolong's `until` into a goal; satisfied says
 * whether and how a goal is met; reopenGoals rebuilds the goals of the applied actions' untils after
 * a restore (checkpoint.ts).
 */
import type { Action, Until } from "../scene/types.js";
import type { TimelineCore } from "./core.js";

const INF = Number.POSITIVE_INFINITY;

/** Compute at least until `tLimit` or until `eLimit` collisions and stops in total, whichever first
 *  (or until nothing is left to happen). */
export interface Goal {
  tLimit: number;
  eLimit: number;
}

/** The goal of `until` counted from time t and the core's current event total. */
export function goalFrom(c: TimelineCore, until: Until, t: number): Goal {
  return {
    tLimit: until.time === undefined ? INF : t + until.time,
    eLimit: until.events === undefined ? INF : c.eventTotal + until.events,
  };
}

/** How goal `g` is met at the core's current point, or null while it is not. */
export function satisfied(c: TimelineCore, g: Goal): "events" | "idle" | "time" | null {
  if (c.eventTotal >= g.eLimit) return "events";
  const t = c.world.time;
  // "idle": no event is left, and an action still to be applied is one
  if (t > g.tLimit || (t === g.tLimit && c.atTimeLimit))
    return c.idle && c.applied === c.acts.length ? "idle" : "time";
  if (c.idle && c.applied === c.acts.length && g.tLimit === INF) return "idle";
  return null;
}

/** Goals of the applied actions' untils, as they stand at the current point (after a restore). */
export function reopenGoals(c: TimelineCore): void {
  c.goals = [];
  c.dormant = [];
  if (!c.untils) return;
  for (let k = 0; k < c.applied; k++) {
    const a = c.acts[k] as Action;
    if (!a.until) continue;
    const g: Goal = {
      tLimit: a.until.time === undefined ? INF : a.time + a.until.time,
      eLimit: a.until.events === undefined ? INF : (c.actEvents[k] as number) + a.until.events,
    };
    if (c.keep(g)) c.goals.push(g);
  }
}
