/**
 * Duplicate keys in a JSON text (pure). JSON.parse keeps the last of two equal keys in an object
 * without a word, so a hand-edited scene file with `"r": 1, ... "r": 2` would silently lose a value
 * the user wrote. `firstDuplicateKey` scans a text that JSON.parse has already accepted and returns
 * the first key that repeats within one object (keys compared after unescaping, as JSON.parse
 * compares them), with its path in the scene's error style (`actions[2].body.r`) and its line and
 * column, or null. Linear in the text; no recursion, so deep nesting cannot overflow the stack.
 */

export interface DuplicateKey {
  /** Path of the repeated key, e.g. `actions[2].r` (the key itself last). */
  readonly path: string;
  readonly key: string;
  /** 1-based line and column of the second occurrence's opening quote. */
  readonly line: number;
  readonly column: number;
}

interface Frame {
  readonly path: string;
  /** Keys seen so far; null for an array. */
  readonly keys: Set<string> | null;
  /** The array's next element index, or the object's last key. */
  index: number;
  key: string;
}

function childPath(frame: Frame): string {
  if (frame.keys === null) return `${frame.path}[${frame.index}]`;
  return frame.path === "" ? frame.key : `${frame.path}.${frame.key}`;
}

/** End index (exclusive) of the string token starting at the quote at `start`. */
function stringEnd(text: string, start: number): number {
  let i = start + 1;
  while (i < text.length) {
    const c = text.charCodeAt(i);
    if (c === 92)
      i += 2; // backslash: skip the escaped character
    else if (c === 34) return i + 1;
    else i++;
  }
  return i;
}

/** 1-based line and column of character `pos` of `text` (lines end at \n, \r\n or a lone \r). */
export function lineColumn(text: string, pos: number): { line: number; column: number } {
  let line = 1;
  let start = 0;
  for (let i = 0; i < pos; i++) {
    const c = text.charCodeAt(i);
    if (c === 10 || (c === 13 && text.charCodeAt(i + 1) !== 10)) {
      line++;
      start = i + 1;
    }
  }
  return { line, column: pos - start + 1 };
}

/** First key repeated within one object of the (valid) JSON `text`, or null. */
export function firstDuplicateKey(text: string): DuplicateKey | null {
  const stack: Frame[] = [];
  // Whether the next string in the innermost object is a key (after `{` or `,`).
  let expectKey = false;
  let i = 0;
  while (i < text.length) {
    const c = text.charCodeAt(i);
    const top = stack[stack.length - 1];
    if (c === 123 || c === 91) {
      // `{` or `[`: a value starting; its path is the parent's current child.
      const path = top === undefined ? "" : childPath(top);
      stack.push({ path, keys: c === 123 ? new Set() : null, index: 0, key: "" });
      expectKey = c === 123;
      i++;
    } else if (c === 125 || c === 93) {
      stack.pop();
      expectKey = false;
      i++;
    } else if (c === 44) {
      // `,`: the next key of an object, or the next element of an array.
      if (top !== undefined && top.keys === null) top.index++;
      expectKey = top !== undefined && top.keys !== null;
      i++;
    } else if (c === 34) {
      const end = stringEnd(text, i);
      if (expectKey && top !== undefined && top.keys !== null) {
        const key = JSON.parse(text.slice(i, end)) as string;
        top.key = key;
        if (top.keys.has(key)) return { path: childPath(top), key, ...lineColumn(text, i) };
        top.keys.add(key);
        expectKey = false;
      }
      i = end;
    } else i++;
  }
  return null;
}
