/**
 * parseScene(json | object): SceneFile. Validates a scene file v1 completely as far as it can without
 * simulating: JSON syntax, duplicate keys and number literals a double cannot hold (jsonNumbers.ts:
 * 1e999 is refused, not read as Infinity), format and version, every field of every action (checkAction), and the
 * scene rules in time order (sceneRules.ts): ids that exist at each action's time, duplicate ids,
 * overlaps among bodies at time 0 (and among bodies placed at the same later time), overlaps with
 * lines and points at any time. Overlaps with bodies that moved (time > 0) need the simulation:
 * Timeline.fromScene checks those. Throws SceneError (path + reason). Returns the normalized scene
 * (defaults filled in, actions in file order).
 */
import { given } from "../sim/refusalText.js";
import { checkAction } from "./action.js";
import { SceneError } from "./errors.js";
import { isObject, nonNegative, onlyKeys, refuse, vec2 } from "./fields.js";
import { type DuplicateKey, duplicateOf, lineColumn } from "./jsonDuplicates.js";
import { type NumberLiteral, overflowOf } from "./jsonNumbers.js";
import { walkJson } from "./jsonPaths.js";
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
function checkSceneRules(g: number, gravity: readonly [number, number], actions: readonly Action[]): void {
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
  if (/^\s*$/.test(text))
    return ': the text is empty (a scene is a JSON object, {"format": "chapgame", ...})';
  if (pos >= text.length) return ` at the end (${at}): the text stops early`;
  const word = /^(NaN|Infinity|undefined)/.exec(text.slice(pos, pos + 9));
  if (word === null) return ` at ${at}${trailingComma(text, pos)}`;
  const fix = word[1] === "undefined" ? "leave the field out" : "write a finite number";
  return ` at ${at}: JSON has no ${word[1]} (${fix})`;
}

/** The hint for a comma just before the closing } or ] at `pos` (which JSON, unlike JavaScript, refuses). */
function trailingComma(text: string, pos: number): string {
  const c = text[pos];
  if (c !== "}" && c !== "]") return "";
  let i = pos - 1;
  while (i >= 0 && /\s/.test(text[i] as string)) i--;
  return text[i] === "," ? `: JSON allows no comma before ${c} (remove the last comma)` : "";
}

/**
 * V8's own message without its position ("in JSON at position 46", and Chromium's "(line 1 column
 * 47)" after it): the refusal gives the line and column itself, and said them twice in the editor.
 */
function withoutPosition(message: string): string {
  return message.replace(/ in JSON at position \d+(?: \(line \d+ column \d+\))?/, "");
}

/** The scene object's own keys, format and version, as a reader and a writer of version 1 check them. */
export function checkHeader(raw: Record<string, unknown>): void {
  onlyKeys(raw, ["format", "version", "g", "gravity", "actions", "meta"], "");
  if (raw.format !== "chapgame") throw refuse("format", 'must be "chapgame"', raw.format);
  const v = raw.version;
  // Not a number at all ("1", null, missing): say what it must be; `unsupported version "1" (this
  // reader knows 1)` read as if the reader knew 1 and refused it anyway (audit of session 23).
  if (typeof v !== "number") throw refuse("version", "must be the number 1", v);
  if (v !== 1) {
    // A later whole-number version is a file from a newer chapgame: say so (review: the editor
    // showed only "unsupported version 2", which read as a damaged file).
    const newer = Number.isInteger(v) && v > 1;
    throw new SceneError(
      "version",
      `unsupported version ${given(v)} (this reader knows 1)${newer ? ": the file comes from a newer chapgame; open it with that version, or save it there as version 1" : ""}`,
    );
  }
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

/** The refusal of a number literal beyond the largest double (JSON.parse would read it as ±Infinity). */
function overflowError(o: NumberLiteral): SceneError {
  const at = `line ${o.line}, column ${o.column}`;
  const shown = o.literal.length > 40 ? `${o.literal.slice(0, 20)}…${o.literal.slice(-12)}` : o.literal;
  const infinity = o.literal.startsWith("-") ? "-Infinity" : "Infinity";
  const fix =
    /(^|\.)m$/.test(o.path) && infinity === "Infinity"
      ? 'for an immovable body (an infinite mass) write the string "Infinity"; otherwise write a finite number'
      : "write a finite number";
  return new SceneError(
    shortPath(o.path),
    `the number ${shown} at ${at} is beyond the largest double (about 1.8e308): JSON would read it as ${infinity}; ${fix}`,
  );
}

/**
 * JSON text to a value: syntax errors with their line and column, duplicate keys and number
 * literals that overflow refused (SceneError); returns the value and the literals that underflow
 * to 0 (path to literal), to explain a refusal of their field.
 */
function readText(input: string): { raw: unknown; underflow: Map<string, string> } {
  // a leading byte order mark (written by some editors) is not part of the JSON text
  const text = input.charCodeAt(0) === 0xfeff ? input.slice(1) : input;
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch (e) {
    const message = (e as Error).message;
    throw new SceneError("json", `invalid JSON${where(text)} (${printable(withoutPosition(message))})`);
  }
  // One walk over the text (the first problem in text order is reported): JSON.parse keeps the
  // last of two equal keys silently (the first value would be lost), and reads 1e999 as Infinity
  // and 1e-999 as 0 without a word.
  const underflow = new Map<string, string>();
  const found = walkJson<{ dup: DuplicateKey } | { overflow: NumberLiteral }>(text, (t) => {
    const dup = duplicateOf(text, t);
    if (dup !== undefined) return { dup };
    const overflow = overflowOf(text, t, underflow);
    // a number alone at the top level is refused as not a scene (checkScene)
    return overflow !== undefined && overflow.path !== "" ? { overflow } : undefined;
  });
  if (found !== undefined && "dup" in found) {
    const { dup } = found;
    throw new SceneError(
      shortPath(dup.path),
      `duplicate key "${dup.key}" at line ${dup.line}, column ${dup.column}: an object may name a key only once (JSON would keep the last value and drop the first)`,
    );
  }
  if (found !== undefined) throw overflowError(found.overflow);
  return { raw, underflow };
}

/** Paths longer than this are shortened in errors (a key nested a million levels deep in `meta`). */
const PATH_SHOWN_MAX = 200;

/** `path`, its middle elided when it is longer than PATH_SHOWN_MAX characters. */
function shortPath(path: string): string {
  if (path.length <= PATH_SHOWN_MAX) return path;
  const half = PATH_SHOWN_MAX / 2;
  return `${path.slice(0, half)}…(${path.length - PATH_SHOWN_MAX} characters)…${path.slice(-half)}`;
}

/** `e` with the literal that read as 0 named, when its field (or an element of it) wrote one. */
function explainUnderflow(e: unknown, underflow: Map<string, string>): unknown {
  if (!(e instanceof SceneError) || underflow.size === 0) return e;
  let literal = underflow.get(e.path);
  if (literal === undefined)
    for (const [path, lit] of underflow)
      if (path.startsWith(`${e.path}[`)) {
        literal = lit;
        break;
      }
  if (literal === undefined) return e;
  return new SceneError(
    e.path,
    // the literal says more than the value it became ("got 0", or a line's end "got [0, 0]")
    `${e.reason.replace(/ \(got (?:0|\[[^\]]*\])\)$/, "")} (the file writes ${literal}, below the smallest double (about 5e-324): JSON reads it as 0)`,
  );
}

/**
 * Validate a scene file v1, given as JSON text (a leading byte order mark allowed) or as an already
 * parsed object, as far as it can be checked without simulating, and return it normalized: g 9.81
 * and gravity [0, 0] when absent, each addBody's mu 0 and v [0, 0] filled in, actions in file order.
 * Throws SceneError (a ChapgameError): `path` names the field (`actions[3].r`; `json` for a syntax
 * error, with its line and column) and `reason` says what is wrong. A number literal beyond the
 * largest double (1e999: JSON would read it as Infinity) is refused wherever it is (an infinite mass
 * is written "Infinity"). Overlaps with bodies that have moved (actions after time 0) need the
 * simulation: Timeline.fromScene checks those.
 */
export function parseScene(input: string | unknown): SceneFile {
  if (typeof input !== "string") return checkScene(refuseBytes(input), false);
  const { raw, underflow } = readText(input);
  try {
    return checkScene(raw, true);
  } catch (e) {
    throw explainUnderflow(e, underflow);
  }
}

/**
 * parseScene of the text `read()` gives (for the CLI): the text is let go once it is read as JSON,
 * before the scene is checked, where parseScene's caller holds it to the end (150 MB for a million
 * bodies). The same result and errors as parseScene(read()).
 */
export function parseSceneFrom(read: () => string): SceneFile {
  const { raw, underflow } = readFrom(read);
  try {
    return checkScene(raw, true);
  } catch (e) {
    throw explainUnderflow(e, underflow);
  }
}

/** readText of the text `read()` gives, which lives in this call only. */
function readFrom(read: () => string): ReturnType<typeof readText> {
  return readText(read());
}

/** A file read without an encoding (readFileSync(path) gives a Buffer) is bytes, not a scene: its
 *  keys 0, 1, … were refused as `0: unknown field` (review of session 31). */
function refuseBytes(input: unknown): unknown {
  if (!(input instanceof ArrayBuffer || ArrayBuffer.isView(input))) return input;
  const kind = input.constructor.name;
  throw new SceneError(
    "scene",
    `must be the scene's JSON text or its object, not bytes (got ${/^[AEIOU]/.test(kind) ? "an" : "a"} ${kind} of ${input.byteLength} bytes): decode them as UTF-8 first (readFileSync(path, "utf8"), or new TextDecoder().decode(bytes))`,
  );
}

/** The parsed scene value checked and normalized (parseScene's checks after the JSON text's).
 *  `owned`: raw was parsed here from text, so each raw action is let go once its checked copy is
 *  made (a million raw actions held beside their copies took 200 MB); a caller's object is left as
 *  it was. */
function checkScene(raw: unknown, owned: boolean): SceneFile {
  if (!isObject(raw)) throw refuse("scene", "must be a JSON object", raw);
  checkHeader(raw);
  const g = raw.g === undefined ? SCENE_DEFAULTS.g : nonNegative(raw, "g", "");
  const gravity = raw.gravity === undefined ? SCENE_DEFAULTS.gravity : vec2(raw, "gravity", "");
  checkFieldMagnitudes(g, gravity, "");
  if (!Array.isArray(raw.actions)) throw refuse("actions", "must be an array", raw.actions);
  const list: unknown[] = raw.actions;
  const actions: Action[] = [];
  for (let i = 0; i < list.length; i++) {
    actions.push(checkAction(list[i], `actions[${i}]`));
    if (owned) list[i] = null;
  }
  checkSceneRules(g, gravity, actions);
  const scene: SceneFile = { format: "chapgame", version: 1, g, gravity, actions };
  if (raw.meta !== undefined) {
    checkMeta(raw.meta);
    scene.meta = raw.meta;
  }
  return scene;
}
