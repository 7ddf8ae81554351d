/**
 * saveCore(core, cutRecord): everything needed to undo the next operation on a TimelineCore, which
 * may cut the records back to `cutRecord` (records.length when it only appends). Returns the undo.
 * Costs O(bodies + records after cutRecord): apply() and setActions() use it to change nothing when
 * they throw. It holds records by their index: forgetBefore (which renumbers them) must not run
 * between saveCore and its undo; it never does (no Timeline method calls it inside an edit), and the
 * undo refuses to run if it did rather than restore forgotten records inconsistently.
 */
import type { TimelineCore } from "./core.js";
import { MotionTable } from "./motionTable.js";

export function saveCore(c: TimelineCore, cutRecord: number): () => void {
  const saved = {
    world: c.world.clone(),
    acts: c.acts.slice(),
    actEvents: c.actEvents.slice(),
    applied: c.applied,
    table: c.table.data.slice(),
    bodyIds: c.bodyIds.slice(),
    live: new Map(c.live),
    lineIds: c.lineIds.slice(),
    lineNums: new Map(c.lineNums),
    pointIds: c.pointIds.slice(),
    pointNums: new Map(c.pointNums),
    tail: c.records.saveTail(cutRecord),
    keyframes: c.keyframes.slice(),
    counts: { ...c.counts },
    eventTotal: c.eventTotal,
    goals: c.goals.slice(),
    atTimeLimit: c.atTimeLimit,
    groupOpen: c.groupOpen,
    idle: c.idle,
    lastLogged: c.lastLogged,
    lastActionTime: c.lastActionTime,
    eventAfterActions: c.eventAfterActions,
    sortedLive: c.sortedLive,
    pathOf: c.pathOf,
    forgotten: c.forgotten.records,
  };
  return () => {
    if (c.forgotten.records !== saved.forgotten)
      throw new Error("timeline: the history was forgotten during an edit; its undo cannot restore it");
    c.world = saved.world;
    c.acts = saved.acts;
    c.actEvents = saved.actEvents;
    c.applied = saved.applied;
    c.table = new MotionTable();
    c.table.data = saved.table;
    c.bodyIds = saved.bodyIds;
    c.live = saved.live;
    c.lineIds = saved.lineIds;
    c.lineNums = saved.lineNums;
    c.pointIds = saved.pointIds;
    c.pointNums = saved.pointNums;
    c.records.restoreTail(cutRecord, saved.tail);
    c.keyframes = saved.keyframes;
    c.rewrites++;
    c.counts = saved.counts;
    c.eventTotal = saved.eventTotal;
    c.goals = saved.goals;
    c.atTimeLimit = saved.atTimeLimit;
    c.groupOpen = saved.groupOpen;
    c.idle = saved.idle;
    c.lastLogged = saved.lastLogged;
    c.lastActionTime = saved.lastActionTime;
    c.eventAfterActions = saved.eventAfterActions;
    c.sortedLive = saved.sortedLive;
    c.pathOf = saved.pathOf;
  };
}
