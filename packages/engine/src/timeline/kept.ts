/**
 * What a Timeline whose start was forgotten (forget.ts) still answers and accepts. The kept history
 * starts at keyframes[0] (time `historyStart`, log entry `firstEvent` = core.forgotten.records); log
 * entries keep their global numbers.
 *
 * - Reads: an index below firstEvent throws a RangeError naming the start of the log; so does a
 *   time before historyStart given to a read whose answer could lie in the forgotten part
 *   (nextEventTime, eventsBetween, eventIndexAt; stateAt says it through its range). prevEventTime answers from
 *   the kept log (null when no kept entry lies before t), as it answers null before the first entry.
 *   Entries logged AT historyStart before the cut (the actions the first kept keyframe follows,
 *   events of that instant before it) are forgotten with the rest: the log starts at firstEvent.
 * - Edits: an edit is recomputed from the last keyframe before it, at worst keyframes[0], so it must
 *   lie after what keyframes[0] holds: an action at a time before historyStart, or at historyStart
 *   when that instant's actions were applied before the keyframe and the edit would not simply join
 *   them (the keyframe follows later events of that instant), is refused with a SceneError. Edits
 *   that pass are recomputed exactly as on a timeline that never forgot.
 */
import { SceneError } from "../scene/errors.js";
import type { Action } from "../scene/types.js";
import { given } from "../sim/refusalText.js";
import { firstChange } from "./actionData.js";
import type { TimelineCore } from "./core.js";
import { historyStart } from "./forget.js";
import type { Keyframe } from "./keyframe.js";

/** Whether anything was forgotten (then keyframes[0] is not the scene's start). */
export function forgot(c: TimelineCore): boolean {
  return c.forgotten.records > 0;
}

/** Where the log starts, for messages: `entry 340 (t = 5.2)`. */
function logStart(c: TimelineCore): string {
  return `entry ${c.forgotten.records} (t = ${historyStart(c)})`;
}

/** The earliest time a read accepts: the start of the kept history, or without history the last
 *  logged entry (only the current motions are known). */
export function earliestTime(c: TimelineCore): number {
  return c.history ? historyStart(c) : c.lastLogged;
}

/** How to keep what forgetBefore drops, for the refusals of reads before it. */
const KEEP_HISTORY = "to keep it, call forgetBefore with an earlier time, or not at all";

/**
 * Why a read before the earliest readable time is refused, naming that time and how to keep more:
 * without history (history: false) only the span since the last logged entry can be read; after
 * forgetBefore, only the kept history.
 */
export function earliestReadable(c: TimelineCore): string {
  if (!c.history)
    return `this timeline keeps no history (history: false), so the earliest readable time is ${c.lastLogged}, its last logged event or action: to read earlier times, create the Timeline with history: true (the default)`;
  const start = historyStart(c);
  return `the history before ${start} was forgotten (forgetBefore), so the earliest readable time is ${start} (the log starts at ${logStart(c)}): ${KEEP_HISTORY}`;
}

/** A log index (already checked to be in [0, eventCount)) as an index into core.records; a
 *  RangeError naming `method` when it was forgotten. */
export function keptIndex(c: TimelineCore, method: string, i: number): number {
  const first = c.forgotten.records;
  if (i < first)
    throw new RangeError(
      `${method}(index): must be at least ${first}, the first entry kept (got ${i}): event ${i} was forgotten (forgetBefore), the log starts at ${logStart(c)}: ${KEEP_HISTORY}`,
    );
  return i - first;
}

/** A time given to a read (`name` of `method`) that looks into the log from t on: a RangeError when
 *  t is before the kept history. */
export function keptTime(c: TimelineCore, method: string, name: string, t: number): number {
  if (forgot(c) && t < historyStart(c))
    throw new RangeError(
      `${method}(${name}): must be >= ${historyStart(c)} (got ${given(t)}): ${earliestReadable(c)}`,
    );
  return t;
}

/**
 * Whether an edit whose first changed action is `d` in the sorted list, at time `cut`, can be
 * recomputed from the kept history (see the header): after keyframes[0]'s actions, and at its time
 * only when the keyframe follows that instant's action group or precedes every action there.
 */
function editable(c: TimelineCore, d: number, cut: number): boolean {
  const kf = c.keyframes[0] as Keyframe;
  const m = kf.actionCount;
  if (d < m || cut < kf.time) return false;
  return cut > kf.time || kf.afterActions || m === 0 || (c.acts[m - 1] as Action).time < kf.time;
}

function refusal(c: TimelineCore, cut: number): string {
  const start = historyStart(c);
  return cut < start
    ? `must be at or after ${start}: the history before it was forgotten (forgetBefore)`
    : `must be after ${start}: the history was forgotten up to there (forgetBefore), and that instant's actions or events before the cut are gone`;
}

/** apply's check: an action at time t inserted at index `insertAt` of the sorted actions. Throws a
 *  SceneError (path `action.time`) when it would change the forgotten history. */
export function checkKeptApply(c: TimelineCore, insertAt: number, t: number): void {
  if (forgot(c) && !editable(c, insertAt, t)) throw new SceneError("action.time", refusal(c, t));
}

/**
 * setActions' check: `sorted` (the new list in applying order; sorted[k] is the caller's
 * actions[order[k]]) against the current actions. Throws a SceneError naming the first changed
 * action of the new list (`actions[i].time`), or `actions` when an action is missing, if the change
 * reaches into the forgotten history.
 */
export function checkKeptActions(c: TimelineCore, sorted: readonly Action[], order: readonly number[]): void {
  if (!forgot(c)) return;
  const acts = c.acts;
  const { d, cut } = firstChange(acts, sorted);
  if (d === sorted.length && d === acts.length) return;
  const inNew = sorted[d]?.time ?? Number.POSITIVE_INFINITY;
  if (editable(c, d, cut)) return;
  if (inNew === cut) throw new SceneError(`actions[${order[d]}].time`, refusal(c, cut));
  throw new SceneError(
    "actions",
    `must keep the action at ${cut} (${(acts[d] as Action).type}): ${refusal(c, cut).replace("must be ", "edits must be ")}`,
  );
}
