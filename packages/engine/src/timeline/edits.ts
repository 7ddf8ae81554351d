/**
 * The edits of a Timeline on its core (Timeline.apply and Timeline.setActions keep the argument
 * checks, the listeners and the headless instant record; the contracts are theirs):
 * - applyToCore(c, a, keepHorizon, checkLater, instant): inserts the checked action `a` at its time.
 *   At or after the horizon it computes forward to it; before, it restores the last keyframe before
 *   it (or the spare restart point after it, restartPoint.ts), replays and recomputes (up to the old horizon, or less: ApplyOptions). Without history, an
 *   action at the horizon's instant joins that instant's group (headlessInstant.ts). On any error the
 *   core is as it was (undo.ts) and an error naming a later action it made invalid says so. Returns
 *   the headless instant record to keep (null with history).
 * - actionsOnCore(c, sorted, order, fresh): replaces the action list (sorted in apply order; `order`
 *   maps each to its index in the caller's list, for messages). The history up to the first change
 *   is kept: when it lies after the horizon (or at it, where an apply would append) nothing is cut
 *   and the computation goes on from the horizon; otherwise it recomputes from the keyframe (or the
 *   spare restart point) before the first change, or from scratch on a fresh core. Returns the core to use. Atomic likewise.
 */
import { SceneError } from "../scene/errors.js";
import type { Action } from "../scene/types.js";
import { firstChange, restartKeyframe, restartsAt } from "./actionData.js";
import { restoreKeyframe } from "./checkpoint.js";
import type { TimelineCore } from "./core.js";
import { goalFrom, reopenGoals } from "./goals.js";
import { type HeadlessInstant, instantHolds, noteInstant, reapplyInstant } from "./headlessInstant.js";
import { checkKeptActions, checkKeptApply, forgot } from "./kept.js";
import type { Keyframe } from "./keyframe.js";
import { restoreSpare, spareFits, spareSlot } from "./restartPoint.js";
import { type EditScope, saveCore } from "./undo.js";

const INF = Number.POSITIVE_INFINITY;

/** The scope of an edit that restarts from keyframe k, or from the spare restart point. */
function restartScope(c: TimelineCore, k: number, spare: boolean, insertAt?: number): EditScope {
  const scope: EditScope = { fromKeyframe: spare ? spareSlot(c) : k, worldReplaced: true };
  if (insertAt !== undefined) scope.insertAt = insertAt;
  if (spare) scope.restart = c.spare as Keyframe;
  return scope;
}

function restartRecord(c: TimelineCore, k: number, spare: boolean): number {
  return (spare ? (c.spare as Keyframe) : (c.keyframes[k] as Keyframe)).record;
}

function restart(c: TimelineCore, k: number, spare: boolean): void {
  if (spare) restoreSpare(c);
  else restoreKeyframe(c, k);
}

/** An error of the recomputed future that names a later action: said to come from this one. */
function laterActionRefusal(e: unknown): unknown {
  if (e instanceof SceneError && e.path.startsWith("actions["))
    return new SceneError(e.path, `${e.reason} (once this action is in place)`);
  return e;
}

export function applyToCore(
  c: TimelineCore,
  a: Action,
  keepHorizon: boolean,
  checkLater: boolean,
  instant: HeadlessInstant | null,
): HeadlessInstant | null {
  let insertAt = c.acts.length;
  while (insertAt > 0 && (c.acts[insertAt - 1] as Action).time > a.time) insertAt--;
  const forward = c.appendsAt(a.time);
  checkKeptApply(c, insertAt, a.time);
  if (!forward && !c.history && instantHolds(instant, c, a.time)) {
    try {
      reapplyInstant(c, instant, a);
    } catch (e) {
      throw laterActionRefusal(e);
    }
    return instant;
  }
  if (!forward && !c.history)
    throw new SceneError(
      "action.time",
      a.time === c.horizon
        ? `must be after ${a.time}: the events that instant's actions caused are computed, and without history (history: false) the instant cannot be computed again; apply it before computing past the actions at ${a.time}, or keep history`
        : `must be >= the horizon ${c.horizon} (history is off)`,
    );
  let k = 0;
  let spare = false;
  if (!forward) {
    const kfs = c.keyframes;
    for (k = kfs.length - 1; k > 0; k--) {
      const kf = kfs[k] as Keyframe;
      if (restartsAt(kf, insertAt, a.time, c.acts)) break;
    }
    spare = spareFits(c, insertAt, a.time, k);
  }
  // Only what this edit can change is kept (undo.ts); forward, the undo also serves a later action
  // at the same instant without history (headlessInstant.ts: the lists only grow meanwhile).
  const scope = forward
    ? { fromKeyframe: c.rawKeyframes.length - 1, insertAt, worldReplaced: false, forward: true }
    : restartScope(c, k, spare, insertAt);
  const undo = saveCore(c, forward ? c.records.length : restartRecord(c, k, spare), scope);
  c.spareAt = a.time >= c.horizon ? a.time : null;
  try {
    const oldHorizon = c.horizon;
    if (!forward) restart(c, k, spare);
    c.acts.splice(insertAt, 0, a);
    // the others by their index in `actions` as the caller knows it (without this one)
    c.pathOf = (i) => (i === insertAt ? "action" : `actions[${i > insertAt ? i - 1 : i}]`);
    if (!forward) {
      reopenGoals(c);
      // keepHorizon false: only as far as the last action (each is still validated), not the old
      // horizon; with checkLater false only as far as this action (later ones checked by prolong).
      const lastAction = (c.acts[c.acts.length - 1] as Action).time;
      const tLimit = keepHorizon
        ? oldHorizon
        : checkLater
          ? Math.max(a.time, Math.min(oldHorizon, lastAction))
          : a.time;
      c.goals.push({ tLimit, eLimit: INF });
    }
    c.drive(INF, { tLimit: a.time, eLimit: INF });
    if (!c.untils && a.until) c.goals.push(goalFrom(c, a.until, a.time));
    c.drive(INF, null);
    c.pathOf = (i) => `actions[${i}]`;
  } catch (e) {
    undo();
    throw laterActionRefusal(e);
  } finally {
    c.spareAt = null;
  }
  if (!c.history) return forward ? noteInstant(instant, c, a, undo) : null;
  return instant;
}

/**
 * Whether the history computed so far holds for a new action list whose first change is action `d`
 * at time `cut` (firstChange): every applied action is unchanged, and the change lies after the
 * horizon, or at it where an apply would append there (core.appendsAt: the last entry logged is
 * before it or that instant's action group, which the changed actions then join, as they would
 * when building from scratch). The computation up to the horizon did not depend on the actions after
 * it (splitting a computation at an action's time changes nothing), so computing on from there
 * gives what building from scratch gives. The goals reconcile themselves: an until met only
 * because no action was left (core.dormant) is revived by the next group applied, and one kept open
 * by an action since removed is found met by the next drive.
 */
function keepsHistory(c: TimelineCore, d: number, cut: number): boolean {
  return d >= c.applied && (cut > c.horizon || (cut === c.horizon && c.appendsAt(cut)));
}

export function actionsOnCore(
  c: TimelineCore,
  sorted: Action[],
  order: readonly number[],
  fresh: () => TimelineCore,
): TimelineCore {
  const oldHorizon = c.horizon;
  // Actions are named by their index in the list given, also when a later prolong applies them
  // (with compute: false, as the CLI runs a file): a file's actions[0] is its first action, not
  // the earliest. The next apply() names them by their index in `actions` again.
  const pathOf = (k: number) => `actions[${order[k]}]`;
  checkKeptActions(c, sorted, order);
  const { d, cut } = firstChange(c.acts, sorted);
  if (keepsHistory(c, d, cut)) {
    // Only computing forward (or nothing): what it may change is what an apply at the horizon may.
    const undo = saveCore(c, c.records.length, {
      fromKeyframe: c.rawKeyframes.length - 1,
      worldReplaced: false,
      forward: true,
    });
    try {
      c.acts = sorted;
      c.pathOf = pathOf;
      driveAfterSet(c, oldHorizon);
    } catch (e) {
      undo();
      throw e;
    }
    return c;
  }
  // after forgetBefore, keyframe 0 is the start of the kept history: a restart point, not scratch
  const k = c.history ? restartKeyframe(c.keyframes, d, cut, c.acts) : 0;
  const spare = c.history && spareFits(c, d, cut, k);
  if (spare || k > 0 || forgot(c)) {
    const undo = saveCore(c, restartRecord(c, k, spare), restartScope(c, k, spare));
    try {
      restart(c, k, spare);
      c.acts = sorted;
      c.pathOf = pathOf;
      reopenGoals(c);
      driveAfterSet(c, oldHorizon);
    } catch (e) {
      undo();
      throw e;
    }
    return c;
  }
  const core = fresh();
  core.acts = sorted;
  core.pathOf = pathOf;
  // compute: false applies only the actions at time 0 (with the untils option, their untils
  // wait for a prolong: they are not computed here)
  driveAfterSet(core, oldHorizon > 0 ? oldHorizon : null);
  return core;
}

/** After setActions put the new list in place: a compute: true core computes up to `horizon` (the
 *  old one; null: no goal) and on, until every action is applied and their untils are met; a
 *  compute: false one stays where it is (the keyframe restored, 0 for a fresh core, or the horizon
 *  it kept), its actions due there applied: its caller computes further when it needs to. */
function driveAfterSet(c: TimelineCore, horizon: number | null): void {
  if (c.eager) {
    if (horizon !== null) c.goals.push({ tLimit: horizon, eLimit: INF });
    c.drive(INF, null);
  } else c.applyDue();
}
