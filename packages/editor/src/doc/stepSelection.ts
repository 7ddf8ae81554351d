/**
 * The selection after Undo or Redo goes from scene `from` to scene `to` (whole scenes,
 * doc/history.ts). A step that only takes back the removal of one body, line or point (the Undo of
 * a Delete, which removes the selection) selects that object again, as it was before the Delete; a
 * step that removes the selected object (the Redo of that Delete) selects nothing, as the Delete
 * left it. Any other step keeps the selection (one whose object a step takes away altogether, the
 * Undo of its Add, is dropped by store/selectionGuard.ts). Actions are compared by content
 * (actionDiff.ts). Pure.
 */
import type { Action, SceneFile } from "../engineTypes";
import type { Selection } from "../store/uiStore";
import { actionsMinus } from "./actionDiff";

const REMOVED = { removeBody: "body", removeLine: "line", removePoint: "point" } as const;

/** The object an action removes, or null when it removes none. */
function removedBy(a: Action): NonNullable<Selection> | null {
  const kind = a.type in REMOVED ? REMOVED[a.type as keyof typeof REMOVED] : null;
  return kind === null || !("id" in a) ? null : { kind, id: a.id };
}

export function selectionAfterStep(from: SceneFile, to: SceneFile, selection: Selection): Selection {
  const gone = actionsMinus(from.actions, to.actions);
  const came = actionsMinus(to.actions, from.actions);
  const restored = came.length === 0 && gone.length === 1 ? removedBy(gone[0]!) : null;
  if (restored !== null) return same(restored, selection) ? selection : restored;
  return came.some((a) => same(removedBy(a), selection)) ? null : selection;
}

function same(a: Selection, b: Selection): boolean {
  return a !== null && b !== null && a.kind === b.kind && a.id === b.id;
}
