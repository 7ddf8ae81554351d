/**
 * applyGroup(core): applies every scheduled action at the core World's current time, each validated
 * first against the scene at that time (sceneRules.ts; not the group at time 0 of a scene parseScene
 * checked already: core.startChecked), then performed on the World (applyAction.ts),
 * tracked in the registry (body, line and point numbers) and the motion table, logged as an action
 * record, and its `until` turned into a goal when the core takes untils (eager, or the untils option). Ends with a keyframe, owed
 * (checkpoint.ts): one per instant, a group applied one call at a time at the same instant replaces
 * the previous one (kept as the spare restart point when it was taken: restartPoint.ts). The scene
 * the actions are checked against is kept for the next call at the same instant (openView).
 */
import { checkAndApply, SceneView } from "../scene/sceneRules.js";
import type { Action } from "../scene/types.js";
import { applyToWorld, touchedBodies } from "./applyAction.js";
import { oweKeyframe, settleKeyframe } from "./checkpoint.js";
import type { TimelineCore } from "./core.js";
import { goalFrom } from "./goals.js";
import type { Keyframe } from "./keyframe.js";
import { K_ACTION } from "./records.js";
import { noteInstantStart } from "./restartPoint.js";

/** Apply every scheduled action at the World's current time (validated first). */
export function applyGroup(c: TimelineCore): void {
  const w = c.world;
  const t = w.time;
  const groupStart = c.records.length;
  // A group at the instant of the last one with nothing logged since joins it: its keyframe, owed
  // or taken, is replaced. Otherwise the owed one is taken now, before anything changes.
  const joinsOwed = c.owed !== null && c.owed.time === t && c.owed.record === groupStart;
  if (!joinsOwed) settleKeyframe(c);
  const kfs = c.rawKeyframes;
  const last = kfs[kfs.length - 1];
  const joinsTaken =
    !joinsOwed &&
    last !== undefined &&
    kfs.length > 1 &&
    last.afterActions &&
    last.time === t &&
    last.record === groupStart;
  if (c.history && !joinsOwed && !joinsTaken) noteInstantStart(c);
  // untils met only by idleness count on: building from scratch, these actions were pending then
  if (c.dormant.length > 0) {
    for (const g of c.dormant) c.goals.push(g);
    c.dormant = [];
  }
  // the group at time 0 of a scene parseScene checked is not checked again (core.startChecked)
  const checked = c.startChecked && t === 0 && c.applied === 0;
  c.startChecked = false;
  const view = checked ? null : openView(c);
  while (c.applied < c.acts.length && (c.acts[c.applied] as Action).time === t) {
    const k = c.applied;
    const a = c.acts[k] as Action;
    const path = c.pathOf(k);
    if (view !== null) checkAndApply(view, a, path);
    applyToWorld(w, a, path);
    // an action's record holds the number of the body it removes (keyframeDelta.ts reads it)
    const removed = a.type === "removeBody" ? (c.live.get(a.id) as number) : 0;
    track(c, a);
    c.actEvents[k] = c.eventTotal;
    c.counts.action++;
    c.lastLogged = t;
    c.lastActionTime = t;
    c.eventAfterActions = false;
    if (c.history) c.records.push(t, K_ACTION, k, removed, 0, 0, 0, 0);
    if (c.untils && a.until) c.goals.push(goalFrom(c, a.until, t));
    c.applied++;
  }
  c.idle = false;
  // events at t that the actions cause are still to be processed (advance up to t does it)
  c.atTimeLimit = false;
  c.groupOpen = true;
  if (view !== null)
    c.view = { view, world: w, applied: c.applied, events: c.eventTotal, records: c.records.length };
  if (!c.history) return;
  // Actions applied one call at a time at the same instant (an editor or a script adding bodies)
  // would stack one keyframe each: the previous one is redundant when nothing happened since, but
  // it is the point between the instant's actions an edit of the last one restarts from.
  if (joinsTaken) {
    c.spare = kfs.pop() as Keyframe;
    c.rewrites++;
  }
  oweKeyframe(c);
}

/**
 * The scene at the World's time for checking a group's actions: the one the last group at this
 * instant checked and updated, when nothing else happened since (same World object, no action
 * applied and nothing computed or logged since), else a new lazy view of the World (its lines and
 * points copied: a scene built one obstacle per apply copied every obstacle per apply). Positions
 * at the instant do not change, and the World is only ever changed by applyGroup, restores (a new
 * World) and undos (another World object).
 */
function openView(c: TimelineCore): SceneView {
  const w = c.world;
  const o = c.view;
  if (
    o !== null &&
    o.world === w &&
    o.view.time === w.time &&
    o.applied === c.applied &&
    o.events === c.eventTotal &&
    o.records === c.records.length
  )
    return o.view;
  c.view = null;
  // the World is the lazy view's source: each action is applied to it once checked
  return SceneView.lazy({
    time: w.time,
    g: w.g,
    gravity: w.gravity,
    bodies: () => w.bodies(),
    hasBody: (id) => w.hasBody(id),
    body: (id) => w.body(id),
    forEachBodyNear: (x, y, r, visit) => w.forEachBodyNear(x, y, r, visit),
    forEachBodyNearSegment: (x1, y1, x2, y2, visit) => w.forEachBodyNearSegment(x1, y1, x2, y2, visit),
    lines: w.lines(),
    points: w.points(),
  });
}

/** Update the registry and the motion table (from the World's own motions) after action `a`. */
function track(c: TimelineCore, a: Action): void {
  const w = c.world;
  if (a.type === "removeBody") {
    c.live.delete(a.id);
    c.sortedLive = null;
  } else if (a.type === "addBody") {
    if (c.sortedLive !== null) c.liveAdded.push(c.bodyIds.length);
    c.live.set(a.id, c.bodyIds.length);
    c.bodyIds.push(a.id);
    if (c.history) c.table.ensure(c.bodyIds.length); // without history the table is not used
  } else if (a.type === "addLine") {
    c.lineNums.set(a.id, c.lineIds.length);
    c.lineIds.push(a.id);
  } else if (a.type === "removeLine") c.lineNums.delete(a.id);
  else if (a.type === "addPoint") {
    c.pointNums.set(a.id, c.pointIds.length);
    c.pointIds.push(a.id);
  } else if (a.type === "removePoint") c.pointNums.delete(a.id);
  if (!c.history) return;
  const touched = touchedBodies(a);
  const ids = touched === "all" ? [...c.live.keys()] : touched === null ? [] : [touched];
  for (const id of ids) c.table.setFromWorld(c.live.get(id) as number, w.motion(id), w.body(id));
}
