/**
 * checkOptions(options): the Timeline constructor's options validated (SceneError naming the key:
 * unknown keys, g and gravity as in scene files, magnitudes included; history and compute booleans) with the defaults
 * filled in (g 9.81, gravity [0, 0], history and compute true; untils true with compute, else false). checkSceneOptions: fromScene's
 * options, which must not carry g or gravity (they come from the scene). Options that are not an
 * object (null, a number, an array) are refused as the World refuses them: `options: must be an
 * object with fields … (got null)`.
 */
import { SceneError } from "../scene/errors.js";
import { isObject, nonNegative, onlyKeys, refuse, vec2 } from "../scene/fields.js";
import { checkFieldMagnitudes } from "../scene/magnitudes.js";
import { SCENE_DEFAULTS, type Vec2 } from "../scene/types.js";
import type { TimelineOptions } from "./types.js";

export interface CheckedOptions {
  g: number;
  gravity: Vec2;
  history: boolean;
  compute: boolean;
  /** the actions' untils are goals (always with compute) */
  untils: boolean;
}

export function checkOptions(options: TimelineOptions): CheckedOptions {
  mustBeObject(options, ["g", "gravity", "history", "compute"]);
  const o = options as Record<string, unknown>;
  // `untils` is internal (the CLI's): accepted, never offered in the list of known fields
  const { untils: _internal, ...documented } = o;
  onlyKeys(documented, ["g", "gravity", "history", "compute"], "");
  for (const key of ["history", "compute", "untils"])
    if (o[key] !== undefined && typeof o[key] !== "boolean")
      throw refuse(key, "must be true or false", o[key]);
  const checked: CheckedOptions = {
    g: o.g === undefined ? SCENE_DEFAULTS.g : nonNegative(o, "g", ""),
    gravity:
      o.gravity === undefined
        ? [SCENE_DEFAULTS.gravity[0], SCENE_DEFAULTS.gravity[1]]
        : vec2(o, "gravity", ""),
    history: options.history !== false,
    compute: options.compute !== false,
    untils: options.compute !== false || options.untils === true,
  };
  checkFieldMagnitudes(checked.g, checked.gravity, "");
  return checked;
}

export function checkSceneOptions(options: Omit<TimelineOptions, "g" | "gravity">): void {
  mustBeObject(options, ["history", "compute"]);
  for (const key of ["g", "gravity"])
    if (Object.hasOwn(options, key))
      throw new SceneError(key, "unknown field (fromScene takes g and gravity from the scene)");
}

/** SceneError `options: must be an object with fields …` for options that are not a plain object. */
function mustBeObject(options: unknown, fields: readonly string[]): void {
  if (!isObject(options))
    throw refuse("options", `must be an object with fields ${fields.join(", ")}`, options);
}
