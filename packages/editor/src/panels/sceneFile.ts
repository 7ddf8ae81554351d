/**
 * Save file: downloads the scene as `scene.chapgame.json` (format v1, sceneIo.sceneText). One function
 * for the header's Save file button and Ctrl/Cmd+S (keyboard.ts), `saveScene`, which also says in
 * the message bar that the file was saved and under which name (the page said nothing: whether a
 * save happened was left to the browser's download bar).
 */
import { sceneText } from "../doc/sceneIo";
import type { SceneFile } from "../engineTypes";

export const SAVE_NAME = "scene.chapgame.json";

export function saveSceneFile(doc: SceneFile, page: Document = document): void {
  const blob = new Blob([sceneText(doc)], { type: "application/json" });
  const a = page.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = SAVE_NAME;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** Saves the editor's scene (saveSceneFile) and says so in the message bar, with the file's name. */
export function saveScene(
  editor: { doc: SceneFile; info(text: string): void },
  page: Document = document,
): void {
  saveSceneFile(editor.doc, page);
  editor.info(`Saved the scene as ${SAVE_NAME} (in the browser's downloads).`);
}
