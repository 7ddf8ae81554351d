/**
 * Scene text in and out (format v1). Parsing and validation are the engine's (parseScene throws
 * SceneError whose message names the path, e.g. `actions[3].r: must be a positive finite number`).
 */
import { parseScene, serializeScene } from "@chapgame/engine";
import type { SceneFile } from "../engineTypes";

export function parseSceneText(text: string): SceneFile {
  return parseScene(text);
}

export function sceneText(scene: SceneFile): string {
  return serializeScene(scene);
}
