/**
 * Start-up: the worker and its client, the Editor, the first scene (a shared link in the URL, else
 * the autosave, else the default preset), autosave on every scene change, playback and keyboard.
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

export function firstScene(): {
  scene: SceneFile;
  from: "url" | "autosave" | "preset";
  error: string | null;
} {
  let error: string | null = null;
  try {
    const fromUrl = sceneFromHash(window.location.hash);
    if (fromUrl) return { scene: fromUrl, from: "url", error };
  } catch (e) {
    error = `Shared link: ${(e as Error).message}`;
  }
  const saved = loadAutosave(window.localStorage);
  if (saved) return { scene: saved, from: "autosave", error };
  return { scene: buildPreset(DEFAULT_PRESET), from: "preset", error };
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
  // A shared link is loaded once; from then on the autosave keeps the user's edits across reloads.
  if (first.from === "url") history.replaceState(null, "", window.location.pathname + window.location.search);
  let err = await editor.loadScene(first.scene, { undoable: false });
  if (err !== null && first.from !== "preset")
    err = await editor.loadScene(buildPreset(DEFAULT_PRESET), { undoable: false });
  if (first.error) editor.ui.setState({ message: { text: first.error, tone: "error" } });

  let savedRevision = client.getSnapshot().docRevision;
  let timer: ReturnType<typeof setTimeout> | null = null;
  client.subscribe(() => {
    const info = client.getSnapshot();
    if (info.docRevision === savedRevision || timer !== null) return;
    timer = setTimeout(() => {
      timer = null;
      const now = client.getSnapshot();
      savedRevision = now.docRevision;
      if (now.doc) saveAutosave(window.localStorage, now.doc);
    }, AUTOSAVE_DELAY_MS);
  });
  startPlayback(editor);
  bindKeyboard(editor);
  Object.assign(window, { chapgame: editor, chapgameStats: drawStats, chapgameResetStats: resetDrawStats });
  return editor;
}
