/**
 * Scene text in and out (format v1). Parsing and validation are the engine's (parseScene throws
 * SceneError with a path); this module only adapts them for the editor.
 */
import type { SceneFile } from "../engineTypes";

export function parseSceneText(text: string): SceneFile {
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (e) {
    throw new Error(`JSON: ${(e as Error).message}`);
  }
  const s = json as SceneFile;
  if (!s || typeof s !== "object" || s.format !== "chapgame") throw new Error('format: must be "chapgame"');
  if (s.version !== 1) throw new Error("version: must be 1");
  if (!Array.isArray(s.actions)) throw new Error("actions: must be an array");
  return { format: "chapgame", version: 1, g: s.g ?? 9.81, gravity: s.gravity ?? [0, 0], actions: s.actions };
}

export function sceneText(scene: SceneFile): string {
  return JSON.stringify(scene, null, 1);
}
