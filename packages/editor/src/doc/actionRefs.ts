/**
 * Naming actions for the user, who sees no action indices: the engine refuses an edit that makes a
 * LATER action invalid with a path `actions[i]` (its index in the action list the engine was given,
 * in time order). explainRefusal keeps the engine's message as it is and appends which action that
 * is ("— actions[11] is the action at t = 4 s: update body "b1" (remove it from the Event log)").
 * Pure.
 */
import type { Action } from "../engineTypes";

/** An action type in words, as the Event log's kind column shows it ("give velocity", "set global"). */
export function actionWords(type: string): string {
  return type.replace(/[A-Z]/g, (c) => ` ${c.toLowerCase()}`);
}

/** An action named for the user, not by the scene file's type: "update body "b1"", "give velocity
 *  to "a"", or the words alone for an action without an id ("set global"). */
export function describeEntry(type: string, id: string | null): string {
  if (id === null) return actionWords(type);
  return `${actionWords(type)}${type === "giveVelocity" ? " to" : ""} ${JSON.stringify(id)}`;
}

/** describeEntry of an action. */
export function describeAction(a: Action): string {
  return describeEntry(a.type, "id" in a ? a.id : null);
}

/** The index `i` of a path that starts with `actions[i]`, or null. */
export function actionIndexOf(path: string | null): number | null {
  const m = path === null ? null : /^actions\[(\d+)\]/.exec(path);
  return m === null ? null : Number(m[1]);
}

/**
 * The message shown for a refused edit: `message` unchanged, followed by which action `actions[i]`
 * is when `path` starts with `actions[i]` and `actions` (the list the engine's index refers to)
 * holds it; otherwise `message` alone.
 */
export function explainRefusal(message: string, path: string | null, actions: readonly Action[]): string {
  const i = actionIndexOf(path);
  const a = i === null ? undefined : actions[i];
  if (a === undefined) return message;
  const t = Number(a.time.toPrecision(6));
  return `${message} — actions[${i}] is the action at t = ${t} s: ${describeAction(a)} (remove it from the Event log)`;
}
