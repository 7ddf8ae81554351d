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
 * intermediate state between the two, which nothing reads, is no longer checked. Only the action
 * right before merges: another action between them (another object's, or a removal) would then be
 * applied after the merged fields, and the placement checks could differ. An edit with an `until`,
 * or a removal or an add, never merges.
 * A merged action that changes nothing (changesNothing: m = 2, then m = 1 again, sets what the body
 * had before either edit) is dropped (the host, remote/host.ts): the scene, its file and its Event
 * log are then the scene's without either edit, bit for bit. An add never changes nothing, nor does
 * an action with an `until`. For a body that is also the future the engine gives the merged action,
 * which the World's updateBody takes as no change and keeps the motion of; the two separate actions
 * differed from it in the last bits, restarting the motion from the same state and rounding it anew
 * (mergeEdit.prop.test.ts: random series of edits, at a collision's instant too, give the separate
 * actions' future, or, when the merged action changes nothing, the future without it). Undo still
 * undoes one edit: it restores the whole scene before it (doc/history.ts), with the action as it
 * was. Pure.
 */
import type { Action, SceneState, Vec2 } from "../engineTypes";

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

const sameVec = (a: Vec2, b: Vec2): boolean => Object.is(a[0], b[0]) && Object.is(a[1], b[1]);

/**
 * Whether the update `a` sets only what `before` (the state at its time, after the actions of that
 * instant before it) already holds, every value the same number (Object.is): a merged edit that put
 * back what its first edit changed. Adds, removals and actions with an `until` are never "nothing".
 */
export function changesNothing(a: Action, before: SceneState): boolean {
  if (a.until !== undefined) return false;
  const fields = fieldsOf(a);
  const same = (has: Record<string, unknown>) =>
    Object.entries(fields).every(([k, v]) =>
      Array.isArray(v) ? sameVec(v as unknown as Vec2, has[k] as Vec2) : Object.is(v, has[k]),
    );
  switch (a.type) {
    case "updateBody":
    case "giveVelocity": {
      const b = before.bodies.find((s) => s.id === a.id);
      return b !== undefined && same({ x: b.x, y: b.y, r: b.r, m: b.m, mu: b.mu, v: [b.vx, b.vy] });
    }
    case "updateLine": {
      const l = before.lines.find((s) => s.id === a.id);
      return l !== undefined && same({ p1: l.p1, p2: l.p2, kind: l.kind });
    }
    case "updatePoint": {
      const p = before.points.find((s) => s.id === a.id);
      return p !== undefined && same({ p: p.p });
    }
    case "setGlobal":
      return same({ g: before.g, gravity: before.gravity });
    default:
      return false;
  }
}
