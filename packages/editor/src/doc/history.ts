/**
 * Undo/redo of scene edits as a pure value: each entry is a whole scene (immutable, actions shared
 * between entries), so undoing is `timeline.setActions` / reload of the previous entry.
 * Only edits enter the history; time, speed and selection never do. Every edit made clears Redo,
 * also one an Undo took back during its check (takenBack; that Undo then puts it first in Redo).
 */
import type { SceneFile } from "../engineTypes";

export interface History {
  past: readonly SceneFile[];
  future: readonly SceneFile[];
}

export const EMPTY_HISTORY: History = { past: [], future: [] };

/** Maximum number of undo steps kept. */
export const HISTORY_LIMIT = 200;

/** Records that `before` was replaced by an edit: it becomes the undo target, redo is cleared. */
export function record(h: History, before: SceneFile): History {
  const past = [...h.past, before];
  if (past.length > HISTORY_LIMIT) past.shift();
  return { past, future: [] };
}

/**
 * Records that an edit was made and at once taken back by the Undo bound to it (during its check,
 * doc/undoIntents.ts), before being recorded: as `record` then `undo`, it clears Redo (the edits
 * undone before it are obsolete) and leaves the past as it was. Its Undo, at its turn, puts the
 * taken-back scene first in Redo (editorUndo.ts).
 */
export function takenBack(h: History): History {
  return h.future.length === 0 ? h : { past: h.past, future: [] };
}

/** The scene to go back to and the history after undoing from `current`; null when nothing to undo. */
export function undo(h: History, current: SceneFile): { scene: SceneFile; history: History } | null {
  const scene = h.past[h.past.length - 1];
  if (!scene) return null;
  return { scene, history: { past: h.past.slice(0, -1), future: [current, ...h.future] } };
}

/** The scene to go forward to and the history after redoing from `current`; null when nothing to redo. */
export function redo(h: History, current: SceneFile): { scene: SceneFile; history: History } | null {
  const scene = h.future[0];
  if (!scene) return null;
  return { scene, history: { past: [...h.past, current], future: h.future.slice(1) } };
}
