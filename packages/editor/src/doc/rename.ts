/**
 * Renaming a body, line or point everywhere in a scene's action list (a rename is an edit of the
 * whole history: the object keeps one id from its creation on). Pure; refuses an empty id and an id
 * another object of the kind has, in the form of the engine's refusals (sim/refusalText.ts):
 * `label: must … (got "id")`, the label the id cell's (`b1 id`), the id typed in double quotes with
 * JSON escapes as the engine quotes ids (the refusal said `b1 id: "b2" is already used by another
 * body`, quoted by hand and before the reason: an id with a quote in it read ambiguously).
 */
import type { Action, SceneFile } from "../engineTypes";

export type ObjectKind = "body" | "line" | "point";

const KIND_OF: Record<string, ObjectKind> = {
  addBody: "body",
  giveVelocity: "body",
  updateBody: "body",
  removeBody: "body",
  addLine: "line",
  updateLine: "line",
  removeLine: "line",
  addPoint: "point",
  updatePoint: "point",
  removePoint: "point",
};

export function kindOf(a: Action): ObjectKind | null {
  return kindOfType(a.type);
}

/** The kind of object an action type acts on (setGlobal, or an unknown type: null). */
export function kindOfType(type: string): ObjectKind | null {
  return KIND_OF[type] ?? null;
}

/** The scene with `from` renamed to `to` for objects of `kind`; throws a message when refused. */
export function renameObject(scene: SceneFile, kind: ObjectKind, from: string, to: string): SceneFile {
  // named as the other cells' refusals are: the object, then the column (audit of session 20)
  const label = `${from} id`;
  if (to === "") throw new Error(refusedId(label, "must not be empty", to));
  if (to !== from && scene.actions.some((a) => kindOf(a) === kind && "id" in a && a.id === to))
    throw new Error(refusedId(label, `must not be the id of another ${kind}`, to));
  const actions = scene.actions.map((a) =>
    kindOf(a) === kind && "id" in a && a.id === from ? { ...a, id: to } : a,
  );
  return { ...scene, actions };
}

/** `label: reason (got "id")`: an id is text whatever it looks like, so always quoted (as `12`, `"12"`). */
function refusedId(label: string, reason: string, id: string): string {
  return `${label}: ${reason} (got ${JSON.stringify(id)})`;
}
