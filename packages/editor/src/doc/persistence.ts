/**
 * Keeping work: autosave to localStorage and shareable URLs (the scene as base64url JSON in the
 * location hash, `#scene=...`). Pure encode/decode plus thin storage access.
 */
import type { SceneFile } from "../engineTypes";
import { parseSceneText, sceneText } from "./sceneIo";

export const AUTOSAVE_KEY = "chapgame.editor.autosave.v1";

export function encodeSceneForUrl(scene: SceneFile): string {
  const bytes = new TextEncoder().encode(JSON.stringify(scene));
  let bin = "";
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

/** The scene in a link's code; throws a plain message when the code is damaged or cut short. */
export function decodeSceneFromUrl(code: string): SceneFile {
  let text: string;
  try {
    const b64 = code.replace(/-/g, "+").replace(/_/g, "/");
    const bin = atob(b64 + "=".repeat((4 - (b64.length % 4)) % 4));
    const bytes = Uint8Array.from(bin, (c) => c.charCodeAt(0));
    text = new TextDecoder("utf-8", { fatal: true }).decode(bytes);
  } catch {
    throw new Error("the scene code after #scene= is damaged or cut short (copy the whole link)");
  }
  return parseSceneText(text);
}

/** The scene in a location hash like `#scene=...`, or null when there is none. */
export function sceneFromHash(hash: string): SceneFile | null {
  const m = /^#?scene=(.+)$/.exec(hash);
  return m?.[1] ? decodeSceneFromUrl(m[1]) : null;
}

export function shareUrl(location: { origin: string; pathname: string }, scene: SceneFile): string {
  return `${location.origin}${location.pathname}#scene=${encodeSceneForUrl(scene)}`;
}

/**
 * Writes the autosave; null on success, else a message for the user. When the scene cannot be
 * stored (storage full or disabled), the older autosave is removed: a reload must not bring back an
 * older scene as if it were the latest.
 */
export function saveAutosave(storage: Storage, scene: SceneFile): string | null {
  const text = sceneText(scene);
  try {
    storage.setItem(AUTOSAVE_KEY, text);
    return null;
  } catch {
    try {
      storage.removeItem(AUTOSAVE_KEY);
    } catch {
      // storage disabled altogether: nothing to remove
    }
    const mb = (text.length / 1e6).toFixed(1);
    return `Autosave failed: the browser's storage refused the scene (${mb} MB of JSON). A reload will not keep it: use Save file.`;
  }
}

export function loadAutosave(storage: Storage): SceneFile | null {
  const text = storage.getItem(AUTOSAVE_KEY);
  if (!text) return null;
  try {
    return parseSceneText(text);
  } catch {
    return null;
  }
}
