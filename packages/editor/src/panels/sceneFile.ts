/**
 * Save file: downloads the scene as `scene.chapgame.json` (format v1, sceneIo.sceneText). One function
 * for the header's Save file button and Ctrl/Cmd+S (keyboard.ts).
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
