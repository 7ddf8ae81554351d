/**
 * Duplicate keys in a JSON text (pure). JSON.parse keeps the last of two equal keys in an object
 * without a word, so a hand-edited scene file with `"r": 1, ... "r": 2` would silently lose a value
 * the user wrote. `firstDuplicateKey` scans a text that JSON.parse has already accepted and returns
 * the first key that repeats within one object (keys compared after unescaping, as JSON.parse
 * compares them), with its path in the scene's error style (`actions[2].body.r`) and its line and
 * column, or null. Linear in the text; no recursion (jsonPaths.ts walks it).
 */
import { type JsonToken, lineColumn, walkJson } from "./jsonPaths.js";

export { lineColumn } from "./jsonPaths.js";

export interface DuplicateKey {
  /** Path of the repeated key, e.g. `actions[2].r` (the key itself last). */
  readonly path: string;
  readonly key: string;
  /** 1-based line and column of the second occurrence's opening quote. */
  readonly line: number;
  readonly column: number;
}

/** First key repeated within one object of the (valid) JSON `text`, or null. */
export function firstDuplicateKey(text: string): DuplicateKey | null {
  return walkJson(text, (t) => duplicateOf(text, t)) ?? null;
}

/** One token of walkJson: the key if it repeats one of its object (for a walk that also looks for
 *  other things: parse.ts). */
export function duplicateOf(text: string, t: JsonToken): DuplicateKey | undefined {
  return t.kind === "key" && t.repeated
    ? { path: t.path, key: t.key, ...lineColumn(text, t.pos) }
    : undefined;
}
