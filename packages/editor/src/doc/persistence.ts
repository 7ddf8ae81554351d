/**
 * Shareable URLs: the scene as base64url JSON in the location hash (`#scene=...`). Pure encode and
 * decode. (The autosave is in autosaveSlots.ts.)
 */
import type { SceneFile } from "../engineTypes";
import { namedTextRefusal } from "./actionRefs";
import { parseSceneText, sceneText } from "./sceneIo";

/**
 * The link code of a scene: its scene-file text (serializeScene writes infinite masses as
 * "Infinity", which plain JSON.stringify turned into null: audit of session 15), without the
 * file's indentation.
 */
export function encodeSceneForUrl(scene: SceneFile): string {
  const compact = JSON.stringify(JSON.parse(sceneText(scene)));
  const bytes = new TextEncoder().encode(compact);
  let bin = "";
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

/**
 * The scene in a link's code; throws a plain message when the code is damaged or cut short, or the
 * engine's refusal of the scene (an action named by what it does: doc/actionRefs.ts).
 */
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
  try {
    return parseSceneText(text);
  } catch (e) {
    throw new Error(namedTextRefusal(e, text)); // an action named as the author knows it
  }
}

/** The scene in a location hash like `#scene=...`, or null when there is none. */
export function sceneFromHash(hash: string): SceneFile | null {
  const m = /^#?scene=(.+)$/.exec(hash);
  return m?.[1] ? decodeSceneFromUrl(m[1]) : null;
}

/**
 * The longest link Share offers. Chromium refuses URLs over 2 MiB (the editor audit's 3.2 MB link of
 * 20,000 discs failed to open with ERR_ABORTED after "Link copied"); a little under it.
 */
export const MAX_SHARE_URL_CHARS = 2_000_000;

/** Why `url` cannot be shared as a link (too long to open), or null. */
export function shareLinkProblem(url: string): string | null {
  if (url.length <= MAX_SHARE_URL_CHARS) return null;
  const mb = (url.length / 1e6).toFixed(1);
  return `This scene's link would be ${mb} MB, longer than browsers open (about 2 MB): use Save to share it as a file.`;
}

export function shareUrl(location: { origin: string; pathname: string }, scene: SceneFile): string {
  return `${location.origin}${location.pathname}#scene=${encodeSceneForUrl(scene)}`;
}
