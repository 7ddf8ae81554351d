/**
 * The time a tab was at, kept across a reload of that tab. When the page goes (pagehide), the
 * current time and a fingerprint of the scene are written to sessionStorage (this tab only, like its
 * autosave id). At start, a tab whose first scene is that same scene (its own autosave, restored by
 * the reload) goes back to that time: computed up to it first when it lies past the horizon the
 * scene's calculation settings give, with the usual progress and Cancel. Any other first scene (a
 * shared link, another tab's autosave, the default preset) starts at 0, as a fresh tab does. Storage
 * that refuses to write or read (private modes, quota) keeps nothing and says nothing: the scene
 * itself is the autosave's and is unaffected.
 */
import { sceneText } from "./doc/sceneIo";
import type { Editor } from "./editor";
import type { SceneFile } from "./engineTypes";

/** sessionStorage: `{ "t": time, "scene": fingerprint }` of this tab when its page last went. */
export const TIME_KEY = "chapgame.editor.tab.time";

/** A short fingerprint of a scene's text (FNV-1a, 32 bits, and the length): equal texts, equal prints. */
export function sceneFingerprint(scene: SceneFile): string {
  const text = sceneText(scene);
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return `${h.toString(16)}:${text.length}`;
}

/** The time kept for `scene` in `session`, or null (none kept, another scene, unreadable). */
export function keptTime(session: Storage, scene: SceneFile): number | null {
  let raw: string | null;
  try {
    raw = session.getItem(TIME_KEY);
  } catch {
    return null;
  }
  if (raw === null) return null;
  try {
    const v = JSON.parse(raw) as { t?: unknown; scene?: unknown };
    const ok = typeof v.t === "number" && Number.isFinite(v.t) && v.t > 0;
    return ok && v.scene === sceneFingerprint(scene) ? (v.t as number) : null;
  } catch {
    return null;
  }
}

/** Writes the editor's time and scene when the page goes; returns a function that stops it. */
export function keepTimeOnLeave(editor: Editor, win: Window, session: Storage): () => void {
  const onHide = () => {
    const doc = editor.client.getSnapshot().doc;
    if (doc === null) return;
    try {
      session.setItem(TIME_KEY, JSON.stringify({ t: editor.ui.getState().t, scene: sceneFingerprint(doc) }));
    } catch {
      // nothing kept: a reload starts at 0
    }
  };
  win.addEventListener("pagehide", onHide);
  return () => win.removeEventListener("pagehide", onHide);
}

/** At start: back to the time kept for the scene now loaded, if any (see the header). */
export async function restoreKeptTime(editor: Editor, session: Storage): Promise<void> {
  const doc = editor.client.getSnapshot().doc;
  if (doc === null) return;
  const t = keptTime(session, doc);
  if (t !== null) await editor.goTo(t);
}
