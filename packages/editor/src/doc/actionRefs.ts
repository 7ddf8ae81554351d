/**
 * Naming actions for the user, who sees no action indices: the engine refuses an action of a scene
 * (a later action an edit makes invalid, one refused when the computation reaches it, one of a file
 * opened) with a path `actions[i]` (its index in the action list the engine was given). Its
 * messages are a contract and stay as they are; the editor names the action as the author knows it,
 * by its time, what it does and its object ("the action at t = 4 s that updates body "b1""), the
 * engine's path kept in parentheses for whoever edits the JSON and its reason after it
 * (namedRefusal; explainRefusal adds where to remove it). Actions are read as plain data, so an
 * action of a file the engine refused is named too, as far as its fields say. Pure.
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

/** What each action type does, said of its object `id` (JSON-quoted). */
const DOES: Record<string, (id: string) => string> = {
  addBody: (id) => `adds disc ${id}`,
  giveVelocity: (id) => `gives velocity to ${id}`,
  updateBody: (id) => `updates body ${id}`,
  removeBody: (id) => `removes body ${id}`,
  addLine: (id) => `adds line ${id}`,
  updateLine: (id) => `updates line ${id}`,
  removeLine: (id) => `removes line ${id}`,
  addPoint: (id) => `adds point ${id}`,
  updatePoint: (id) => `updates point ${id}`,
  removePoint: (id) => `removes point ${id}`,
};

/**
 * An action as the author knows it: "the action at t = 1 s that adds disc "b3"", "the action at
 * t = 2 s that sets the globals"; `a` is plain data (a file's action may lack a field or hold a
 * wrong one: what it holds is said, "the action at t = 3 s" for an unknown type). Null when it
 * says neither a time nor what it does.
 */
export function actionName(a: unknown): string | null {
  if (typeof a !== "object" || a === null) return null;
  const { time, type, id } = a as { time?: unknown; type?: unknown; id?: unknown };
  const at =
    typeof time === "number" && Number.isFinite(time) ? ` at t = ${Number(time.toPrecision(6))} s` : "";
  const does =
    type === "setGlobal"
      ? "sets the globals"
      : typeof type === "string" && typeof id === "string" && DOES[type] !== undefined
        ? (DOES[type] as (id: string) => string)(JSON.stringify(id))
        : null;
  if (at === "" && does === null) return null;
  return `the action${at}${does === null ? "" : ` that ${does}`}`;
}

/**
 * The engine's refusal `message` of path `path` in the author's terms when the path names an
 * action of `actions` (the list its index refers to): "the action at t = 1 s that adds disc "b3"
 * (actions[1]): body "b3" would overlap body "a" at time 1" (the reason as the engine gave it);
 * otherwise `message` as it is.
 */
export function namedRefusal(message: string, path: string | null, actions: readonly unknown[]): string {
  const i = actionIndexOf(path);
  const name = i === null ? null : actionName(actions[i]);
  if (name === null) return message;
  const head = `${path}: `;
  const reason = message.startsWith(head) ? message.slice(head.length) : message;
  return `${name} (${path}): ${reason}`;
}

/** The `actions` of scene text as plain data, as far as it is JSON holding them (else none). */
function actionsOfText(source: string): readonly unknown[] {
  try {
    const actions = (JSON.parse(source) as { actions?: unknown } | null)?.actions;
    return Array.isArray(actions) ? actions : [];
  } catch {
    return [];
  }
}

/**
 * The engine's refusal `e` of scene text `source` (parseScene's SceneError, whose `actions[i]` is
 * the text's own index) as namedRefusal says it, the action read from the text.
 */
export function namedTextRefusal(e: unknown, source: string): string {
  const path = (e as { path?: unknown } | null)?.path;
  const text = e instanceof Error ? e.message : String(e);
  return namedRefusal(text, typeof path === "string" ? path : null, actionsOfText(source));
}

/** `text` with its first letter upper-case (a name that starts a message). */
export const capitalized = (text: string): string => text.charAt(0).toUpperCase() + text.slice(1);

/**
 * The message shown for a refused edit: the engine's, its action `actions[i]` named for the author
 * (namedRefusal) and where to remove it, when `path` starts with `actions[i]` and `actions` (the
 * list the engine's index refers to) holds it; otherwise `message` alone.
 */
export function explainRefusal(message: string, path: string | null, actions: readonly Action[]): string {
  const named = namedRefusal(message, path, actions);
  if (named === message) return message;
  return `${capitalized(named)} (remove it from the Event log)`;
}
