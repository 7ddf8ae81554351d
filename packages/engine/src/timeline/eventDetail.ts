/**
 * detailOf: one log entry with its participating bodies' exact states just before and just after it
 * (Timeline.eventDetail; the EventDetail type says which bodies). Nothing is sampled at t ± ε: the
 * log cursor (logCursor.ts) hands over the motions just before record i, evaluated at the entry's
 * time (the same numbers `describe` derives the contact from), then replays record i, whose stored
 * new velocities give the state just after. An action record changes no motion in the replay: the
 * state after it is the keyframe taken after its instant's group of actions (actionGroup.ts), which
 * holds the motions the World restarted.
 */
import type { Action } from "../scene/types.js";
import type { BodyState } from "../sim/types.js";
import { touchedBodies } from "./applyAction.js";
import type { TimelineCore } from "./core.js";
import { type Keyframe, keyframeAtRecord, liveNumber, loadMotions } from "./keyframe.js";
import { MotionTable } from "./motionTable.js";
import { K_ACTION, K_BODY_BODY } from "./records.js";
import { describe } from "./replay.js";
import type { EventBody, EventDetail } from "./types.js";

/**
 * The detail of record i, given the motions just before it in `table` (with `kf`, the keyframe in
 * force there). `step()` replays record i into `table` (the cursor moves past it).
 */
export function detailOf(
  core: TimelineCore,
  i: number,
  table: MotionTable,
  kf: Keyframe,
  step: () => void,
): EventDetail {
  const rec = core.records;
  const event = describe(core, i, table, kf);
  const t = rec.time[i] as number;
  if (rec.kind[i] === K_ACTION) return { ...event, bodies: actionBodies(core, i, table, kf) };
  const a = rec.a[i] as number;
  const nums = rec.kind[i] === K_BODY_BODY ? [a, rec.b[i] as number] : [a];
  const before = nums.map((n) => table.state(n, core.bodyIds[n] as string, t));
  step();
  const bodies = nums.map(
    (n, k): EventBody => ({
      id: core.bodyIds[n] as string,
      before: before[k] as BodyState,
      after: table.state(n, core.bodyIds[n] as string, t),
    }),
  );
  return { ...event, bodies };
}

/** The body an action entry names (addBody, giveVelocity, updateBody, removeBody), or null. */
function actionBody(a: Action): string | null {
  if (a.type === "removeBody") return a.id;
  const touched = touchedBodies(a);
  return touched === "all" ? null : touched;
}

/** Before: the motions before the instant's group of actions (`table`, `kf`); after: the keyframe
 *  taken right after that group (the action records at t from i on end at its record). */
function actionBodies(core: TimelineCore, i: number, table: MotionTable, kf: Keyframe): EventBody[] {
  const rec = core.records;
  const id = actionBody(core.acts[rec.a[i] as number] as Action);
  if (id === null) return [];
  const t = rec.time[i] as number;
  let end = i + 1;
  while (end < rec.length && rec.kind[end] === K_ACTION && rec.time[end] === t) end++;
  const kfs = core.keyframes;
  const after = kfs[keyframeAtRecord(kfs, end)];
  if (after === undefined || after.record !== end || after.time !== t)
    throw new Error(`timeline: no keyframe after the actions at t = ${t} (record ${i})`);
  const nb = liveNumber(kf, core.bodyIds, id, core.chains);
  const na = liveNumber(after, core.bodyIds, id, core.chains);
  let afterState: BodyState | null = null;
  if (na !== null) {
    const scratch = new MotionTable(Math.max(16, after.bodyCount));
    loadMotions(after, scratch, core.chains);
    afterState = scratch.state(na, id, t);
  }
  return [{ id, before: nb === null ? null : table.state(nb, id, t), after: afterState }];
}
