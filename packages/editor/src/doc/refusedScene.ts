/**
 * A scene the engine refused at start (this tab's autosave, e.g. written by another version, or
 * damaged), kept in localStorage beside the autosave slots until the user dismisses its notice, so
 * that loading the default scene in its place loses nothing: the notice offers it as a file. One
 * entry (the latest); storage that refuses to write keeps nothing, and the notice still shows.
 * Pure functions over a Storage.
 */

/** localStorage: `{ "text": scene text, "reason": the engine's refusal, "savedAt": ms }`. */
export const REFUSED_KEY = "chapgame.editor.refused";

export interface RefusedScene {
  text: string;
  reason: string;
  savedAt: number;
}

/** Keeps `scene`'s text with the reason it was refused; false when the storage refused it. */
export function keepRefused(local: Storage, kept: RefusedScene): boolean {
  try {
    local.setItem(REFUSED_KEY, JSON.stringify(kept));
    return true;
  } catch {
    return false;
  }
}

/** The kept refused scene, or null (none, or unreadable). */
export function readRefused(local: Storage): RefusedScene | null {
  try {
    const raw = local.getItem(REFUSED_KEY);
    if (raw === null) return null;
    const v = JSON.parse(raw) as Partial<RefusedScene>;
    if (typeof v.text !== "string" || typeof v.reason !== "string" || typeof v.savedAt !== "number")
      return null;
    return { text: v.text, reason: v.reason, savedAt: v.savedAt };
  } catch {
    return null;
  }
}

/** Forgets the kept refused scene (its notice dismissed). */
export function dropRefused(local: Storage): void {
  try {
    local.removeItem(REFUSED_KEY);
  } catch {
    // nothing to do: it stays until a later dismissal works
  }
}
