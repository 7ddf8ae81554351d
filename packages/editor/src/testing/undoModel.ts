/**
 * The Undo/Redo a user expects, as a pure reference model for sequence tests of the editor
 * (editorUndoSequences.test.ts): `past` the edits in the scene in the order made, `future` the
 * edits Redo brings back, first one first. Contract: an edit made clears Redo, also one an Undo
 * took back during its check (it alone is then in Redo, `unchecked`: Redo checks it again, and a
 * refusal drops it); a refused or cancelled edit changes nothing; Undo moves the last edit to the
 * front of Redo, Redo moves it back. Edits asked together (each queued behind the one before) with
 * Undos and Redos asked while they are in flight (askedTogether): the Undos are bound to them, the
 * last edit first, and only the last edit can be taken back during its check. What the engine
 * decides (refused or not, taken back or done first) is told to the model, which says what the
 * history must then be.
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

/** What became of an edit asked: made, refused (or cancelled), or taken back by its Undo during its check. */
export type Outcome = "made" | "refused" | "takenBack";

/**
 * Edits asked one after another (each queued behind the one before), then `undos` Undos and
 * `redos` Redos asked while they were all in flight. The first Undo is bound to the last edit, the
 * next to the edit before, and those past the first edit undo the recorded past; an Undo bound to a
 * refused edit does nothing. Only the last edit can be taken back during its check, and only with an
 * Undo bound to it: an Undo bound to an earlier edit waits for its turn, after the later edits' own
 * Undos (taken back at once, the later edits ran on a scene without it, and their Redo entries lost
 * it). Each Redo is bound to the Undo before it, the last one first, and redoes what that Undo took
 * (nothing if it took nothing); `refusedWhenRedone` says whether the check refused an unchecked
 * edit brought back. Throws when an outcome is not possible.
 */
export function askedTogether<E>(
  m: UndoModel<E>,
  edits: readonly (readonly [E, Outcome])[],
  undos: number,
  redos: number,
  refusedWhenRedone: (edit: E) => boolean,
): UndoModel<E> {
  if (redos > undos) throw new Error(`${redos} Redos bound to ${undos} Undos`);
  let out = m;
  edits.forEach(([edit, outcome], i) => {
    if (outcome === "made") out = made(out, edit);
    else if (outcome === "takenBack") {
      if (i !== edits.length - 1 || undos === 0)
        throw new Error(
          `${String(edit)} taken back though ${undos === 0 ? "no Undo was" : "an edit was"} asked after it`,
        );
      out = takenBack(out, edit);
    }
  });
  // Whether each Undo moved an edit to Redo (its Redo then brings it back).
  const took: boolean[] = [];
  for (let u = 0; u < undos; u++) {
    const bound = edits[edits.length - 1 - u];
    if (bound !== undefined && bound[1] !== "made") {
      took.push(bound[1] === "takenBack"); // already in Redo; a refused edit's Undo does nothing
      continue;
    }
    took.push(out.past.length > 0);
    out = undone(out);
  }
  for (let r = 0; r < redos; r++) {
    if (!took[undos - 1 - r]) continue;
    const first = out.future[0];
    out = redone(out, first?.unchecked === true && refusedWhenRedone(first.edit));
  }
  return out;
}
