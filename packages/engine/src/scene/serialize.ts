/**
 * serializeScene(scene): the scene as pretty JSON text with a stable key order (format, version, g,
 * gravity, actions, meta; in each action: time, type, then its fields in ACTION_FIELDS order, then
 * until), one action per line. Numbers are written so they read back bit-identical; an infinite
 * value (a mass) is written "Infinity". parseScene(serializeScene(s)) deep-equals parseScene(s).
 * It takes what a scene file holds (a SceneFile, or a file's object as JSON.parse reads it: g and
 * gravity may be left out, a mass may be "Infinity"). Every field, the format and version included,
 * is checked first as parseScene checks it (SceneError naming the field: a scene is never written
 * that could not be read back field by field); the scene rules that need the scene's state (ids,
 * overlaps) are parseScene's. Fields are written as given: a g, a gravity or an action's field left
 * out stays out (no defaults added; parseScene fills the same ones in).
 */

import { ACTION_FIELDS, checkAction } from "./action.js";
import { isObject, nonNegative, refuse, vec2 } from "./fields.js";
import { checkFieldMagnitudes } from "./magnitudes.js";
import { checkMeta } from "./meta.js";
import { checkHeader } from "./parse.js";
import { type Action, SCENE_DEFAULTS, type SceneFile, type Vec2 } from "./types.js";

/** What serializeScene takes: a SceneFile, or a scene file as written, whose g and gravity may be
 *  left out (parseScene gives them their defaults). */
type SceneToWrite = Omit<SceneFile, "g" | "gravity"> & { g?: number | undefined; gravity?: Vec2 | undefined };

function value(v: unknown): string {
  if (typeof v === "number") {
    if (v === Number.POSITIVE_INFINITY) return '"Infinity"';
    if (!Number.isFinite(v)) throw new Error(`serializeScene: cannot write ${v}`);
    if (Object.is(v, -0)) return "-0"; // JSON.stringify would drop the sign
    return JSON.stringify(v);
  }
  if (Array.isArray(v)) return `[${v.map(value).join(", ")}]`;
  return JSON.stringify(v);
}

function actionLine(a: Action): string {
  const o = a as unknown as Record<string, unknown>;
  const parts = [`"time": ${value(a.time)}`, `"type": ${JSON.stringify(a.type)}`];
  for (const [key] of ACTION_FIELDS[a.type])
    if (o[key] !== undefined) parts.push(`${JSON.stringify(key)}: ${value(o[key])}`);
  if (a.until) {
    const u: string[] = [];
    if (a.until.time !== undefined) u.push(`"time": ${value(a.until.time)}`);
    if (a.until.events !== undefined) u.push(`"events": ${value(a.until.events)}`);
    parts.push(u.length === 0 ? `"until": {}` : `"until": { ${u.join(", ")} }`);
  }
  return `{ ${parts.join(", ")} }`;
}

/** Throws SceneError naming the first field parseScene would refuse on its own. */
function checkFields(scene: SceneToWrite): void {
  const raw = scene as unknown as Record<string, unknown>;
  if (!isObject(raw)) throw refuse("scene", "must be an object", raw);
  // A scene of another version, or with a key this version does not have, is refused, not rewritten
  // as version 1 without it.
  checkHeader(raw);
  if (!Array.isArray(raw.actions)) throw refuse("actions", "must be an array", raw.actions);
  // left out, a field is at its default: checked as parseScene reads it
  const g = raw.g === undefined ? SCENE_DEFAULTS.g : nonNegative(raw, "g", "");
  const gravity = raw.gravity === undefined ? SCENE_DEFAULTS.gravity : vec2(raw, "gravity", "");
  checkFieldMagnitudes(g, gravity, "");
  if (raw.meta !== undefined) checkMeta(raw.meta);
  raw.actions.forEach((a, i) => {
    checkAction(a, `actions[${i}]`);
  });
}

/**
 * The scene as JSON text: a stable key order, one action per line, numbers that read back
 * bit-identical (an infinite mass as "Infinity"); parseScene of the text deep-equals parseScene of
 * the scene. It takes what a scene file may hold: `g` and `gravity` may be left out (as in a file;
 * they stay out), and an object JSON.parse read from a valid file is written as it is. Every field
 * is checked first as parseScene checks it (SceneError naming the field, e.g. `actions[0].x`); the
 * rules that need the scene's state (ids that exist, overlaps) are parseScene's.
 */
export function serializeScene(scene: SceneToWrite): string {
  checkFields(scene);
  const lines = ["{", '  "format": "chapgame",', '  "version": 1,'];
  if (scene.g !== undefined) lines.push(`  "g": ${value(scene.g)},`);
  if (scene.gravity !== undefined) lines.push(`  "gravity": ${value(scene.gravity)},`);
  const acts = scene.actions.map((a) => `    ${actionLine(a)}`);
  const tail = scene.meta === undefined ? "" : ",";
  lines.push(
    acts.length === 0 ? `  "actions": []${tail}` : `  "actions": [\n${acts.join(",\n")}\n  ]${tail}`,
  );
  if (scene.meta !== undefined) lines.push(`  "meta": ${JSON.stringify(scene.meta)}`);
  lines.push("}");
  return `${lines.join("\n")}\n`;
}
