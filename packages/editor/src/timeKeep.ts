/**
 * The time a tab was at, and its Calculation settings, kept across a reload of that tab. The
 * settings come back whatever the scene (they are the tab's, like a preference: "300 s ahead" came
 * back as 10, review), before the first scene is computed. When the page goes (pagehide), the
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
import type { CalcSettings } from "./store/uiStore";

/** sessionStorage: `{ "t": time, "scene": fingerprint, "calc": CalcSettings }` of this tab when its
 *  page last went. */
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
    // the scene the autosave writes (while an edit is checked, the one before it): the reload's
    const doc = editor.confirmedDoc();
    if (doc === null) return;
    try {
      const { t, calc } = editor.ui.getState();
      session.setItem(TIME_KEY, JSON.stringify({ t, scene: sceneFingerprint(doc), calc }));
    } catch {
      // nothing kept: a reload starts at 0
    }
  };
  win.addEventListener("pagehide", onHide);
  return () => win.removeEventListener("pagehide", onHide);
}

/** The Calculation settings kept in `session`, or null (none, or not settings the panel could show). */
export function keptCalc(session: Storage): CalcSettings | null {
  try {
    const c = (JSON.parse(session.getItem(TIME_KEY) ?? "null") as { calc?: Partial<CalcSettings> } | null)
      ?.calc;
    if (!c) return null;
    const count = (x: unknown) => typeof x === "number" && Number.isFinite(x) && x > 0;
    const flag = (x: unknown) => typeof x === "boolean";
    if (!(flag(c.useTime) && flag(c.useEvents) && flag(c.autoExtend) && count(c.seconds) && count(c.events)))
      return null;
    return c as CalcSettings;
  } catch {
    return null;
  }
}

/** At start, before the first scene is computed: the Calculation settings the tab had, if kept. */
export function restoreKeptCalc(editor: Editor, session: Storage): void {
  const calc = keptCalc(session);
  if (calc) editor.ui.setState({ calc });
}

/** At start: back to the time kept for the scene now loaded, if any (see the header). */
export async function restoreKeptTime(editor: Editor, session: Storage): Promise<void> {
  const doc = editor.client.getSnapshot().doc;
  if (doc === null) return;
  const t = keptTime(session, doc);
  if (t !== null) await editor.goTo(t);
}
