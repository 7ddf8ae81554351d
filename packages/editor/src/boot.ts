/**
 * Start-up: the worker and its client, the Editor, the first scene (a shared link in the URL, else
 * the autosave of this tab or the newest one, else the default preset; a shared link is one undo
 * step over the autosave; so is the autosave over the scene a load replaced in that tab, kept beside
 * it), autosave per tab (autosave.ts), the time a reloaded tab was at (timeKeep.ts), playback and
 * keyboard.
 */
import { TabAutosave } from "./autosave";
import { browserAutosaveEnv } from "./autosaveEnv";
import { drawStats, resetDrawStats } from "./canvas/drawStats";
import { loadCharacterKeys, pageStorage } from "./characterKeys";
import { sceneFromHash } from "./doc/persistence";
import { keepRefused, readRefused } from "./doc/refusedScene";
import { sceneText } from "./doc/sceneIo";
import { Editor } from "./editor";
import type { SceneFile } from "./engineTypes";
import { bindKeyboard } from "./keyboard";
import { clockTime } from "./newerWork";
import { startPlayback } from "./playback";
import { buildPreset, DEFAULT_PRESET, presetFileName } from "./presets";
import { TimelineClient } from "./remote/client";
import type { Port } from "./remote/protocol";
import { listenForSharedLinks } from "./sharedLink";
import { createUiStore } from "./store/uiStore";
import { keepTimeOnLeave, restoreKeptCalc, restoreKeptTime } from "./timeKeep";

export interface FirstScene {
  scene: SceneFile;
  from: "url" | "autosave" | "preset";
  /**
   * Loaded first, so Undo brings it back: the autosaved scene a shared link replaces, or the scene a
   * load (Clear, a preset, an opened file) replaced before the autosave was written.
   */
  previous: SceneFile | null;
  /** What to say once `scene` is loaded over `previous`. */
  undoNote: string | null;
  error: string | null;
  /** Something to tell about the autosave restored (not this tab's own), or null. */
  note: string | null;
  /** This tab's own autosave when it no longer parses (its text and why), to keep and announce. */
  unreadable?: { text: string; reason: string } | null;
  /** This tab's autosave id: where a refused scene of it is kept (doc/refusedScene.ts). */
  tab?: string;
  /** The file name `scene` came from, which Save file suggests (sceneNames.ts); none when absent. */
  name?: string | null;
}

/** The scene to start with: a shared link in the URL, else the tab's autosave, else the default preset. */
export function firstScene(hash: string, autosave: TabAutosave): FirstScene {
  const first = { ...chooseFirstScene(hash, autosave), tab: autosave.tab };
  return autosave.unreadable ? { ...first, unreadable: autosave.unreadable } : first;
}

function chooseFirstScene(hash: string, autosave: TabAutosave): FirstScene {
  let error: string | null = null;
  const restored = autosave.restore();
  const saved = restored?.slot.scene ?? null;
  const note = restored?.note ?? null;
  try {
    const fromUrl = sceneFromHash(hash);
    if (fromUrl)
      return {
        scene: fromUrl,
        from: "url",
        previous: saved,
        undoNote: "Opened the shared scene. Undo returns to the scene you had before.",
        error,
        note: null,
      };
  } catch (e) {
    error = `Shared link: ${(e as Error).message}`;
  }
  const replaced = restored?.replaced ?? null;
  if (saved)
    return {
      scene: saved,
      name: restored?.slot.name ?? null,
      from: "autosave",
      previous: replaced?.scene ?? null,
      undoNote: replaced
        ? `Restored the autosaved scene. Undo brings back the scene it replaced at ${clockTime(replaced.savedAt)}.`
        : null,
      error,
      note,
    };
  return {
    scene: buildPreset(DEFAULT_PRESET),
    from: "preset",
    previous: null,
    undoNote: null,
    error,
    note: null,
    name: presetFileName(DEFAULT_PRESET),
  };
}

/**
 * Loads the first scene: over `previous` as one undo step when there is one (`undoNote` said), else
 * alone; the default preset when the engine refuses a scene that is not it. A refused autosave is
 * kept in `local` and announced (uiStore refusedScene; RefusedSceneNotice offers it as a file).
 */
export async function loadFirstScene(
  editor: Editor,
  first: FirstScene,
  local: Storage | null = null,
): Promise<void> {
  let err: string | null;
  // This tab's autosave refused (by the engine, or not parsing at all): kept (doc/refusedScene.ts)
  // and said, not lost.
  let refused: { text: string; reason: string } | null = first.unreadable ?? null;
  const previousErr = first.previous ? await editor.loadScene(first.previous, { undoable: false }) : null;
  if (first.previous && previousErr === null) {
    // A shared scene the engine refuses leaves the previous scene loaded (the message says why).
    const named = { name: first.name ?? null };
    if ((await editor.loadScene(first.scene, named)) === null && first.undoNote) editor.info(first.undoNote);
    err = null;
  } else {
    // the autosave a shared link was to be opened over, refused: kept like one restored alone
    if (first.previous && previousErr !== null)
      refused = { text: sceneText(first.previous), reason: previousErr };
    err = await editor.loadScene(first.scene, {
      undoable: false,
      name: first.name ?? null,
      preset: first.from === "preset",
    });
  }
  if (err !== null && first.from === "autosave") refused = { text: sceneText(first.scene), reason: err };
  if (refused) {
    const tab = first.tab ?? null;
    const kept =
      local !== null && tab !== null && keepRefused(local, tab, { ...refused, savedAt: Date.now() });
    editor.ui.setState({ refusedScene: { ...refused, tab: kept ? tab : null } });
  }
  if (err !== null && first.from !== "preset")
    err = await editor.loadScene(buildPreset(DEFAULT_PRESET), {
      undoable: false,
      name: presetFileName(DEFAULT_PRESET),
      preset: true,
    });
  if (first.error) editor.ui.setState({ message: { text: first.error, tone: "error" } });
  else if (first.note) editor.info(first.note);
  // this tab's scene refused at an earlier start, whose notice was not dismissed
  const earlier = local !== null && first.tab ? readRefused(local, first.tab) : null;
  if (earlier && editor.ui.getState().refusedScene === null)
    editor.ui.setState({
      refusedScene: { reason: earlier.reason, text: earlier.text, tab: first.tab ?? null },
    });
}

export async function boot(): Promise<Editor> {
  let worker: Worker | null = null;
  const newPort = (): Port => {
    worker?.terminate();
    worker = new Worker(new URL("./remote/worker.ts", import.meta.url), { type: "module" });
    return worker as unknown as Port;
  };
  const client = new TimelineClient(newPort());
  const editor = new Editor(client, createUiStore({ characterKeys: loadCharacterKeys(pageStorage()) }));
  editor.portFactory = newPort;
  const autosave = new TabAutosave(browserAutosaveEnv());
  const first = firstScene(window.location.hash, autosave);
  // A shared link is loaded once (a broken one too); from then on the autosave keeps the user's
  // edits across reloads. The scene it replaces is loaded first, so Undo brings it back (so is the
  // scene a load replaced before the reload).
  if (/^#?scene=/.test(window.location.hash))
    history.replaceState(null, "", window.location.pathname + window.location.search);
  restoreKeptCalc(editor, window.sessionStorage);
  await loadFirstScene(editor, first, window.localStorage);
  // A reload of this tab goes back to the time it was at (timeKeep.ts), for the same scene only.
  if (first.from === "autosave") void restoreKeptTime(editor, window.sessionStorage);
  keepTimeOnLeave(editor, window, window.sessionStorage);
  // A reloaded tab whose scene is older than another tab's: say so (the notice offers it).
  const newer = autosave.newerOther();
  if (newer) editor.ui.setState({ newerWork: { tab: newer.tab, savedAt: newer.savedAt } });

  autosave.attach(editor, window);
  listenForSharedLinks(editor, window);
  startPlayback(editor);
  bindKeyboard(editor);
  Object.assign(window, { chapgame: editor, chapgameStats: drawStats, chapgameResetStats: resetDrawStats });
  return editor;
}
