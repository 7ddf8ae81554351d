/**
 * The Undo/Redo a user expects, as a pure reference model for sequence tests of the editor
 * (editorUndoSequences.test.ts): `past` the edits in the scene in the order made, `future` the
 * edits Redo brings back, first one first. Contract: an edit made clears Redo, also one an Undo
 * took back during its check (it alone is then in Redo, `unchecked`: Redo checks it again, and a
 * refusal drops it); a refused or cancelled edit changes nothing; Undo moves the last edit to the
 * front of Redo, Redo moves it back. What the engine decides (refused or not, taken back or done
 * first) is told to the model, which says what the history must then be.
 */

export interface Entry<E> {
  edit: E;
  /** Taken back during its check: Redo checks it again (it may be refused then). */
  unchecked: boolean;
}

export interface UndoModel<E> {
  readonly past: readonly E[];
  readonly future: readonly Entry<E>[];
}

export function emptyModel<E>(): UndoModel<E> {
  return { past: [], future: [] };
}

/** An edit made (accepted): it is the next to undo and clears Redo. */
export function made<E>(m: UndoModel<E>, edit: E): UndoModel<E> {
  return { past: [...m.past, edit], future: [] };
}

/** An Undo: the last edit goes first in Redo (nothing when there is none). */
export function undone<E>(m: UndoModel<E>): UndoModel<E> {
  const last = m.past.at(-1);
  if (last === undefined) return m;
  return { past: m.past.slice(0, -1), future: [{ edit: last, unchecked: false }, ...m.future] };
}

/** An edit made and taken back at once by an Undo during its check: Redo holds it alone. */
export function takenBack<E>(m: UndoModel<E>, edit: E): UndoModel<E> {
  return { past: m.past, future: [{ edit, unchecked: true }] };
}

/**
 * A Redo: the first edit of Redo comes back, or, `refused` by its check (only an unchecked one
 * can be), leaves Redo. Throws when the refusal is not possible.
 */
export function redone<E>(m: UndoModel<E>, refused: boolean): UndoModel<E> {
  const [first, ...rest] = m.future;
  if (first === undefined) return m;
  if (refused && !first.unchecked)
    throw new Error(`Redo of ${String(first.edit)} refused though it was checked`);
  return { past: refused ? m.past : [...m.past, first.edit], future: rest };
}
