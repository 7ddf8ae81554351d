/**
 * What Undo and Redo mean while changes are still queued or being checked. Contract: Undo undoes
 * the last change the user asked for when they pressed it (Redo redoes the last one Undo took),
 * whatever becomes of that change later. Scene changes run one after another (EditorSession.serial),
 * so an Undo pressed during an edit's check used to run after it and, when the check refused the
 * edit, undid the edit before instead (an edit lost that the user never asked to undo).
 *
 * Each undoable change gets a Ticket when asked; each Undo or Redo, when asked, is bound to the
 * ticket it will move (a change in flight, or one entry of the recorded history, doc/history.ts).
 * `Intents` is the history as the user sees it on top of the recorded one: tickets on top of the
 * recorded past, tickets in front of the recorded future. When its turn comes an Undo or Redo acts
 * by its ticket's fate (undoTurn, redoTurn). Pure functions over immutable Intents; a ticket's
 * `fate` is set by the session as the change runs. Intents are cleared once no change is queued.
 */
import type { SceneFile } from "../engineTypes";

/**
 * `queued`, `running`: the change is in flight. `done`: it is (or, for a ticket Undo or Redo made
 * of a recorded entry, stands for) an entry of the recorded history. `refused`: it is not in the
 * history (refused, cancelled, or nothing was there to undo or redo). `takenBack`: Undo took it back
 * during its check (an entry not recorded yet: `scene` is the scene that held it).
 */
export type Fate = "queued" | "running" | "done" | "refused" | "takenBack";

export interface Ticket {
  fate: Fate;
  /** For `takenBack`: the scene with the change, which Redo brings back (checked again). */
  scene?: SceneFile;
}

export interface Intents {
  /** Tickets on top of the recorded past, the last one undone first. */
  readonly past: readonly Ticket[];
  /** Tickets in front of the recorded future, the first one redone first. */
  readonly future: readonly Ticket[];
  /**
   * A change was asked since the last reset: it clears the future, so Redo past `future` has
   * nothing. The recorded future itself is cleared when the change is recorded or taken back by
   * its Undo (history.ts record, takenBack), so it stays cleared once these intents are reset; a
   * change refused or cancelled leaves it.
   */
  readonly futureCleared: boolean;
}

export const NO_INTENTS: Intents = { past: [], future: [], futureCleared: false };

/** A new change asked (it becomes the next to undo, and clears Redo). */
export function changeAsked(s: Intents, ticket: Ticket): Intents {
  return { past: [...s.past, ticket], future: [], futureCleared: true };
}

/**
 * An Undo asked: the ticket it is bound to (the last ticket on top of the past, or a new one
 * standing for the recorded past's last entry), moved to the front of the future.
 */
export function undoAsked(s: Intents): { intents: Intents; ticket: Ticket } {
  const ticket = s.past.at(-1) ?? { fate: "done" };
  return { intents: { ...s, past: s.past.slice(0, -1), future: [ticket, ...s.future] }, ticket };
}

/**
 * A Redo asked: the ticket it is bound to (the first of the future, or a new one standing for the
 * recorded future's first entry), moved on top of the past; null when a change asked since cleared
 * the future (nothing to redo).
 */
export function redoAsked(s: Intents): { intents: Intents; ticket: Ticket | null } {
  const first = s.future[0];
  if (first === undefined && s.futureCleared) return { intents: s, ticket: null };
  const ticket = first ?? { fate: "done" };
  return { intents: { ...s, past: [...s.past, ticket], future: s.future.slice(1) }, ticket };
}

/**
 * Whether `ticket` is in the future (an Undo took it): a change that runs so is taken back, unless a
 * change asked after it is queued behind it (its Undo then undoes it at its turn: sceneChanges.ts).
 */
export function isUndone(s: Intents, ticket: Ticket): boolean {
  return s.future.includes(ticket);
}

/**
 * What an Undo does at its turn, by its ticket's fate: `undo` the recorded past's last entry (the
 * ticket's change, or the entry it stands for); `toFuture` record the taken-back change as undone
 * (its scene first in the recorded future, for Redo); `nothing` (the change is not there: refused).
 * A change still in flight cannot be met: it runs before the Undo bound to it.
 */
export function undoTurn(ticket: Ticket): "undo" | "toFuture" | "nothing" {
  if (ticket.fate === "takenBack") return "toFuture";
  return ticket.fate === "done" ? "undo" : "nothing";
}

/** What a Redo does at its turn: `redo` the recorded future's first entry, or `nothing`. */
export function redoTurn(ticket: Ticket | null): "redo" | "nothing" {
  return ticket?.fate === "done" ? "redo" : "nothing";
}

/** Whether Undo has something to undo: the recorded past or a ticket on top of it. */
export function canUndo(s: Intents, recordedPast: number): boolean {
  return s.past.length > 0 || recordedPast > 0;
}

/** Whether Redo has something to redo: a ticket in the future, or the recorded future unless cleared. */
export function canRedo(s: Intents, recordedFuture: number): boolean {
  return s.future.length > 0 || (!s.futureCleared && recordedFuture > 0);
}
