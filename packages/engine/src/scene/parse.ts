/**
 * parseScene(json | object): SceneFile. Validates a scene file v1 completely as far as it can without
 * simulating: JSON syntax, format and version, every field of every action (checkAction), and the
 * scene rules in time order (sceneRules.ts): ids that exist at each action's time, duplicate ids,
 * overlaps among bodies at time 0 (and among bodies placed at the same later time), overlaps with
 * lines and points at any time. Overlaps with bodies that moved (time > 0) need the simulation:
 * Timeline.fromScene checks those. Throws SceneError (path + reason). Returns the normalized scene
 * (defaults filled in, actions in file order).
 */
import { checkAction } from "./action.js";
import { SceneError } from "./errors.js";
import { isObject, nonNegative, onlyKeys, vec2 } from "./fields.js";
import { firstDuplicateKey, lineColumn } from "./jsonDuplicates.js";
import { jsonErrorOffset } from "./jsonSyntax.js";
import { checkFieldMagnitudes } from "./magnitudes.js";
import { checkMeta } from "./meta.js";
import { checkAndApply, SceneView } from "./sceneRules.js";
import { type Action, SCENE_DEFAULTS, type SceneFile } from "./types.js";

/** Indices of `actions` sorted by time, ties in list order (the order actions apply in). */
export function applyOrder(actions: readonly { time: number }[]): number[] {
  const idx = actions.map((_, i) => i);
  return idx.sort((i, j) => (actions[i] as Action).time - (actions[j] as Action).time || i - j);
}

/** Checks the scene rules of `actions` (already field-validated) in time order, without simulating. */
export function checkSceneRules(
  g: number,
  gravity: readonly [number, number],
  actions: readonly Action[],
): void {
  const view = new SceneView(0, g, gravity);
  for (const i of applyOrder(actions)) {
    const a = actions[i] as Action;
    if (a.time > view.time) view.forgetPositions(a.time);
    checkAndApply(view, a, `actions[${i}]`);
  }
}

/**
 * " at line L, column C" of the first character that is not JSON (jsonSyntax.ts: V8 gives an
 * offset for some errors and none for others, such as a NaN), " at the end (line L, column C)" for
 * a text that stops early (a truncated file), and a word on the values JSON does not have.
 */
function where(text: string): string {
  const pos = jsonErrorOffset(text);
  if (pos < 0) return "";
  const { line, column } = lineColumn(text, pos);
  const at = `line ${line}, column ${column}`;
  if (pos >= text.length) return ` at the end (${at}): the text stops early`;
  const word = /^(NaN|Infinity|undefined)/.exec(text.slice(pos, pos + 9));
  if (word === null) return ` at ${at}`;
  const fix = word[1] === "undefined" ? "leave the field out" : "write a finite number";
  return ` at ${at}: JSON has no ${word[1]} (${fix})`;
}

/** The scene object's own keys, format and version, as a reader and a writer of version 1 check them. */
export function checkHeader(raw: Record<string, unknown>): void {
  onlyKeys(raw, ["format", "version", "g", "gravity", "actions", "meta"], "");
  if (raw.format !== "chapgame") throw new SceneError("format", 'must be "chapgame"');
  if (raw.version !== 1)
    throw new SceneError(
      "version",
      `unsupported version ${JSON.stringify(raw.version)} (this reader knows 1)`,
    );
}

/**
 * `message` with control characters written as \u escapes: V8 quotes the start of the text in its
 * JSON errors, and a binary file given as a scene put raw bytes on the user's terminal (the CLI
 * escapes every message the same way: a key or id may hold them too).
 */
export function printable(message: string): string {
  let out = "";
  for (const ch of message) {
    const c = ch.charCodeAt(0);
    out += c < 0x20 || (c >= 0x7f && c <= 0x9f) ? `\\u${c.toString(16).padStart(4, "0")}` : ch;
  }
  return out;
}

/**
 * Validate a scene file v1, given as JSON text (a leading byte order mark allowed) or as an already
 * parsed object, as far as it can be checked without simulating, and return it normalized: g 9.81
 * and gravity [0, 0] when absent, each addBody's mu 0 and v [0, 0] filled in, actions in file order.
 * Throws SceneError (a ChapgameError): `path` names the field (`actions[3].r`; `json` for a syntax
 * error, with its line and column) and `reason` says what is wrong. Overlaps with bodies that have
 * moved (actions after time 0) need the simulation: Timeline.fromScene checks those.
 */
export function parseScene(input: string | unknown): SceneFile {
  let raw: unknown = input;
  if (typeof input === "string") {
    // a leading byte order mark (written by some editors) is not part of the JSON text
    const text = input.charCodeAt(0) === 0xfeff ? input.slice(1) : input;
    try {
      raw = JSON.parse(text);
    } catch (e) {
      const message = (e as Error).message;
      throw new SceneError("json", `invalid JSON${where(text)} (${printable(message)})`);
    }
    // JSON.parse keeps the last of two equal keys silently: the first value would be lost.
    const dup = firstDuplicateKey(text);
    if (dup !== null)
      throw new SceneError(
        dup.path,
        `duplicate key "${dup.key}" at line ${dup.line}, column ${dup.column}: an object may name a key only once (JSON would keep the last value and drop the first)`,
      );
  }
  if (!isObject(raw)) throw new SceneError("scene", "must be a JSON object");
  checkHeader(raw);
  const g = raw.g === undefined ? SCENE_DEFAULTS.g : nonNegative(raw, "g", "");
  const gravity = raw.gravity === undefined ? SCENE_DEFAULTS.gravity : vec2(raw, "gravity", "");
  checkFieldMagnitudes(g, gravity, "");
  if (!Array.isArray(raw.actions)) throw new SceneError("actions", "must be an array");
  const actions = raw.actions.map((a, i) => checkAction(a, `actions[${i}]`));
  checkSceneRules(g, gravity, actions);
  const scene: SceneFile = { format: "chapgame", version: 1, g, gravity, actions };
  if (raw.meta !== undefined) {
    checkMeta(raw.meta);
    scene.meta = raw.meta;
  }
  return scene;
}
