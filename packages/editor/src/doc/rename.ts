/**
 * Renaming a body, line or point everywhere in a scene's action list (a rename is an edit of the
 * whole history: the object keeps one id from its creation on). Pure; refuses an id already in use.
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
  if (to === "") throw new Error(`${from} id: must not be empty`);
  if (to !== from && scene.actions.some((a) => kindOf(a) === kind && "id" in a && a.id === to))
    throw new Error(`${from} id: "${to}" is already used by another ${kind}`);
  const actions = scene.actions.map((a) =>
    kindOf(a) === kind && "id" in a && a.id === from ? { ...a, id: to } : a,
  );
  return { ...scene, actions };
}
