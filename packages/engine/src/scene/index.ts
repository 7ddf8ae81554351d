/** Barrel of src/scene: the public exports of this folder (scene file format v1 and presets). */
export { ACTION_TYPES, checkAction } from "./action.js";
export { SceneError } from "./errors.js";
export { parseScene } from "./parse.js";
export {
  billiardsBreak,
  bouncingBalls,
  brownian,
  dilutedGas,
  type GasOptions,
  galperin,
  newtonsCradle,
  originalDemo,
  type PresetInfo,
  presets,
} from "./presets.js";
export { serializeScene } from "./serialize.js";
export type { Action, ActionType, SceneFile, Until } from "./types.js";
