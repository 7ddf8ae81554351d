/**
 * Start-up: the worker and its client, the Editor, the first scene (a shared link in the URL, else
 * the autosave, else the default preset; a shared link is one undo step over the autosave), autosave
 * after every scene change (and when the page goes), playback and keyboard.
 */
import { drawStats, resetDrawStats } from "./canvas/drawStats";
import { loadAutosave, saveAutosave, sceneFromHash } from "./doc/persistence";
import { Editor } from "./editor";
import type { SceneFile } from "./engineTypes";
import { bindKeyboard } from "./keyboard";
import { startPlayback } from "./playback";
import { buildPreset, DEFAULT_PRESET } from "./presets";
import { TimelineClient } from "./remote/client";
import type { Port } from "./remote/protocol";
import { createUiStore } from "./store/uiStore";

/** Milliseconds of quiet after a scene change before it is autosaved. */
const AUTOSAVE_DELAY_MS = 300;

export interface FirstScene {
  scene: SceneFile;
  from: "url" | "autosave" | "preset";
  /** The autosaved scene a shared link replaces (loaded first, so Undo brings it back). */
  previous: SceneFile | null;
  error: string | null;
}

/** The scene to start with: a shared link in the URL, else the autosave, else the default preset. */
export function firstScene(
  hash: string = window.location.hash,
  storage: Storage = window.localStorage,
): FirstScene {
  let error: string | null = null;
  const saved = loadAutosave(storage);
  try {
    const fromUrl = sceneFromHash(hash);
    if (fromUrl) return { scene: fromUrl, from: "url", previous: saved, error };
  } catch (e) {
    error = `Shared link: ${(e as Error).message}`;
  }
  if (saved) return { scene: saved, from: "autosave", previous: null, error };
  return { scene: buildPreset(DEFAULT_PRESET), from: "preset", previous: null, error };
}

export async function boot(): Promise<Editor> {
  let worker: Worker | null = null;
  const newPort = (): Port => {
    worker?.terminate();
    worker = new Worker(new URL("./remote/worker.ts", import.meta.url), { type: "module" });
    return worker as unknown as Port;
  };
  const client = new TimelineClient(newPort());
  const editor = new Editor(client, createUiStore());
  editor.portFactory = newPort;
  const first = firstScene();
  // A shared link is loaded once (a broken one too); from then on the autosave keeps the user's
  // edits across reloads. The scene it replaces is loaded first, so Undo brings it back.
  if (/^#?scene=/.test(window.location.hash))
    history.replaceState(null, "", window.location.pathname + window.location.search);
  let err: string | null;
  if (first.previous && (await editor.loadScene(first.previous, { undoable: false })) === null) {
    // A shared scene the engine refuses leaves the previous scene loaded (the message says why).
    if ((await editor.loadScene(first.scene)) === null)
      editor.info("Opened the shared scene. Undo returns to the scene you had before.");
    err = null;
  } else err = await editor.loadScene(first.scene, { undoable: false });
  if (err !== null && first.from !== "preset")
    err = await editor.loadScene(buildPreset(DEFAULT_PRESET), { undoable: false });
  if (first.error) editor.ui.setState({ message: { text: first.error, tone: "error" } });

  let savedRevision = client.getSnapshot().docRevision;
  let timer: ReturnType<typeof setTimeout> | null = null;
  let autosaveFailed = false;
  const save = () => {
    if (timer !== null) clearTimeout(timer);
    timer = null;
    const now = client.getSnapshot();
    if (now.docRevision === savedRevision) return;
    savedRevision = now.docRevision;
    const failed = now.doc ? saveAutosave(window.localStorage, now.doc) : null;
    if (failed !== null && !autosaveFailed) editor.ui.setState({ message: { text: failed, tone: "error" } });
    autosaveFailed = failed !== null; // said once, until autosave works again
  };
  client.subscribe(() => {
    if (client.getSnapshot().docRevision === savedRevision || timer !== null) return;
    timer = setTimeout(save, AUTOSAVE_DELAY_MS);
  });
  // A reload or a closed tab within the quiet delay of an edit keeps that edit.
  window.addEventListener("pagehide", save);
  startPlayback(editor);
  bindKeyboard(editor);
  Object.assign(window, { chapgame: editor, chapgameStats: drawStats, chapgameResetStats: resetDrawStats });
  return editor;
}
