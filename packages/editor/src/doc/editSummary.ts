/**
 * summarizeEdit(before, after): one line saying what an edit changed, for the message shown after
 * Undo and Redo (an audit found they said nothing, and undoing an edit at a later time showed no
 * change at all). Actions are compared by content, as multisets (actionDiff.ts). An edit merged
 * into the action before it (doc/mergeEdit.ts: one action of the same object at the same time
 * replaced by another) is said as the fields it changed in that action; a change of the scene's
 * title alone, as what became of the title (sceneTitle.ts). Pure.
 */
import type { Action, SceneFile } from "../engineTypes";
import { actionKey as key, actionsMinus as minus } from "./actionDiff";
import { describeAction } from "./actionRefs";
import { titleChange } from "./sceneTitle";

function at(a: Action): string {
  return `${describeAction(a)} at t = ${Number(a.time.toPrecision(6))} s`;
}

/**
 * "the rename of "a" to "b"" when the change replaced every action of one id by the same actions
 * of another (a rename), else null.
 */
function renameOf(added: Action[], removed: Action[]): string | null {
  if (added.length === 0 || added.length !== removed.length) return null;
  const ids = (list: Action[]) => new Set(list.map((a) => ("id" in a ? a.id : null)));
  const from = [...ids(removed)];
  const to = [...ids(added)];
  if (from.length !== 1 || to.length !== 1 || from[0] === null || to[0] === null) return null;
  const renamed = removed.map((a) => key({ ...a, id: to[0] } as Action));
  const left = minus(added, []).map(key);
  if (renamed.sort().join() !== left.sort().join()) return null;
  return `the rename of ${JSON.stringify(from[0])} to ${JSON.stringify(to[0])}`;
}

/**
 * "the change of x, y in update body "a" at t = 2 s" when `to` replaced `from`, an action of the
 * same object at the same time (a merged edit, or its undo), else null.
 */
function changeOf(from: Action, to: Action): string | null {
  const id = (a: Action) => ("id" in a ? a.id : null);
  if (from.time !== to.time || id(from) !== id(to) || objectOf(from) !== objectOf(to)) return null;
  const a = from as unknown as Record<string, unknown>;
  const b = to as unknown as Record<string, unknown>;
  const fields = [...new Set([...Object.keys(b), ...Object.keys(a)])].filter(
    (k) => k !== "type" && k !== "time" && k !== "id" && JSON.stringify(a[k]) !== JSON.stringify(b[k]),
  );
  if (fields.length === 0) return null;
  return `the change of ${fields.join(", ")} in ${at(to)}`;
}

/** The kind of object an action edits ("body", "line", "point", "globals"). */
function objectOf(a: Action): string {
  if (a.type === "setGlobal") return "globals";
  return /Body|Velocity/.test(a.type) ? "body" : /Line/.test(a.type) ? "line" : "point";
}

export function summarizeEdit(before: SceneFile, after: SceneFile): string {
  const added = minus(after.actions, before.actions);
  const removed = minus(before.actions, after.actions);
  if (added.length === 1 && removed.length === 0) return at(added[0]!);
  if (added.length === 0 && removed.length === 1) return `the removal of ${at(removed[0]!)}`;
  const change = added.length === 1 && removed.length === 1 ? changeOf(removed[0]!, added[0]!) : null;
  if (change !== null) return change;
  const rename = renameOf(added, removed);
  if (rename !== null) return rename;
  const changed = [...added, ...removed];
  if (changed.length > 0) {
    const first = Math.min(...changed.map((a) => a.time));
    return `a change of ${added.length + removed.length} actions, the earliest at t = ${Number(first.toPrecision(6))} s`;
  }
  const globals = before.g !== after.g || before.gravity.join() !== after.gravity.join();
  if (globals) return "a change of the scene's g or gravity";
  return titleChange(before, after) ?? "a change that left the actions as they were";
}
