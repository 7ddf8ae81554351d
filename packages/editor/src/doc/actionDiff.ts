/**
 * What one scene's actions have that another's lack, compared by content (the scenes come from the
 * worker, so the same action is a different object in each), as multisets: what an edit, an undo
 * or a redo changed (editSummary.ts, stepSelection.ts). Pure.
 */
import type { Action } from "../engineTypes";

/** An action's content, as a key. */
export function actionKey(a: Action): string {
  return JSON.stringify(a);
}

/** The actions of `a` that `b` lacks (counting repeats), in the order of `a`. */
export function actionsMinus(a: readonly Action[], b: readonly Action[]): Action[] {
  const left = new Map<string, number>();
  for (const x of b) left.set(actionKey(x), (left.get(actionKey(x)) ?? 0) + 1);
  const out: Action[] = [];
  for (const x of a) {
    const n = left.get(actionKey(x)) ?? 0;
    if (n > 0) left.set(actionKey(x), n - 1);
    else out.push(x);
  }
  return out;
}
