/**
 * A scene the engine refused at start (a tab's autosave, e.g. written by another version, or
 * damaged), kept in localStorage beside the autosave slots until the user dismisses its notice, so
 * that loading another scene in its place loses nothing: the notice offers it as a file. One entry
 * per tab (a refusal in another tab replaced the first one: review); storage that refuses to write
 * keeps nothing, and the notice still offers the scene from memory. Pure functions over a Storage.
 */

/** localStorage key of tab `tab`'s refused scene: `{ "text", "reason", "savedAt" }`. */
export const refusedKey = (tab: string): string => `chapgame.editor.refused.${tab}`;

export interface RefusedScene {
  text: string;
  reason: string;
  savedAt: number;
}

/** Keeps tab `tab`'s refused scene text with the reason; false when the storage refused it. */
export function keepRefused(local: Storage, tab: string, kept: RefusedScene): boolean {
  try {
    local.setItem(refusedKey(tab), JSON.stringify(kept));
    return true;
  } catch {
    return false;
  }
}

/** The kept refused scene, or null (none, or unreadable). */
export function readRefused(local: Storage, tab: string): RefusedScene | null {
  try {
    const raw = local.getItem(refusedKey(tab));
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
export function dropRefused(local: Storage, tab: string): void {
  try {
    local.removeItem(refusedKey(tab));
  } catch {
    // nothing to do: it stays until a later dismissal works
  }
}
