/**
 * Consecutive edits of one object at one instant are one action: changing a body's x, then its y,
 * then its r in the table at t = 2 gives one `updateBody` with x, y and r, not three actions in
 * the scene file and the Event log; editing a disc at the instant it was added changes its
 * `addBody`. mergedEdit says, for an edit about to be applied to the action list `actions` (in
 * applying order: time, then as given), whether it merges into the action right before the place
 * it would take (the last one at or before its time), and what that action becomes:
 * - into an addBody, updateBody or giveVelocity of the same body at the same time: an updateBody or
 *   giveVelocity (the add keeps its type; a giveVelocity that gains a place or a size becomes an
 *   updateBody);
 * - into an addLine or updateLine of the same line: an updateLine; into an addPoint or
 *   updatePoint of the same point: an updatePoint; into a setGlobal: a setGlobal.
 * The state after the instant is the same: the actions at one instant are applied in order before
 * anything they cause, and the merged action sets each field to its last value. Only the
 * intermediate state between the two, which nothing reads, is no longer checked. One difference
 * in the last bits: an edit that puts back what the action before it changed (m = 2, then m = 1
 * again) merges into an action that changes nothing, which keeps the body's motion (the World's
 * updateBody), so the future is the scene's without either edit bit for bit, where the two actions
 * restarted the motion from the same state and rounded it anew (mergeEdit.prop.test.ts: random
 * series of edits, at a collision's instant too, give the separate actions' future but for that). Only the action
 * right before merges: another action between them (another object's, or a removal) would then be
 * applied after the merged fields, and the placement checks could differ. An edit with an `until`,
 * or a removal or an add, never merges. Undo still undoes one edit: it restores the whole scene
 * before it (doc/history.ts), with the action as it was. Pure.
 */
import type { Action } from "../engineTypes";

/** What names an action rather than sets a field of its object. */
const NOT_FIELDS = new Set(["time", "type", "id", "until"]);

/** The fields an edit sets (all but time, type, id and until). */
function fieldsOf(a: Action): Record<string, unknown> {
  return Object.fromEntries(Object.entries(a).filter(([k]) => !NOT_FIELDS.has(k)));
}

const BODY = new Set(["addBody", "updateBody", "giveVelocity"]);
const LINE = new Set(["addLine", "updateLine"]);
const POINT = new Set(["addPoint", "updatePoint"]);

/** The object an action edits ("body:a", "line:l1", "point:p1", "globals"), or null for one it never merges into. */
function target(a: Action): string | null {
  if (a.type === "setGlobal") return "globals";
  if (BODY.has(a.type)) return `body:${(a as { id: string }).id}`;
  if (LINE.has(a.type)) return `line:${(a as { id: string }).id}`;
  if (POINT.has(a.type)) return `point:${(a as { id: string }).id}`;
  return null;
}

/** Whether `a` is an edit that merges into an earlier one (an update, never an add or a removal). */
function merges(a: Action): boolean {
  return (
    a.until === undefined &&
    (a.type === "updateBody" ||
      a.type === "giveVelocity" ||
      a.type === "updateLine" ||
      a.type === "updatePoint" ||
      a.type === "setGlobal")
  );
}

/** `prev` with the fields `next` sets (both edit the same object). */
function combined(prev: Action, next: Action): Action {
  const merged = { ...prev, ...fieldsOf(next) } as Action;
  // a velocity given, then a place or a size: a giveVelocity holds only v
  if (merged.type === "giveVelocity" && Object.keys(fieldsOf(merged)).some((k) => k !== "v"))
    return { ...merged, type: "updateBody" } as Action;
  return merged;
}

/**
 * The action `next` merges into when applied to `actions` (its index there, and the action that
 * takes its place), or null when it is added as an action of its own (see the module comment).
 */
export function mergedEdit(
  actions: readonly Action[],
  next: Action,
): { index: number; action: Action } | null {
  if (!merges(next)) return null;
  let i = actions.length - 1;
  while (i >= 0 && (actions[i] as Action).time > next.time) i--;
  const prev = actions[i];
  if (prev === undefined || prev.time !== next.time) return null;
  const t = target(prev);
  if (t === null || t !== target(next)) return null;
  return { index: i, action: combined(prev, next) };
}
