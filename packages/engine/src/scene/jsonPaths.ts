/**
 * walkJson(text, visit): visits the keys and the number literals of a text JSON.parse has already
 * accepted, in text order, each with its path in the scene's error style (`actions[2].r`,
 * `actions[0].v[1]`; "" for a value at the top level) and its offset; a key also says whether it
 * repeats a key of the same object (compared after unescaping, as JSON.parse compares them). A
 * token's `path` and `literal` are computed when read, and hold only during its visit (most
 * visitors read neither: building every path cost more than JSON.parse on a 24 MB scene). The
 * walk stops at the first visit that returns a value other than undefined, and returns it. Pure,
 * linear in the text, no recursion (deep nesting cannot overflow the stack). lineColumn(text, pos):
 * 1-based line and column of an offset.
 */

export type JsonToken =
  | {
      readonly kind: "key";
      readonly path: string;
      readonly key: string;
      readonly pos: number;
      readonly repeated: boolean;
    }
  | {
      readonly kind: "number";
      readonly path: string;
      readonly literal: string;
      /** The literal is text[pos, end). */
      readonly pos: number;
      readonly end: number;
    };

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

/** Whether c can be part of a JSON number literal: digits, sign, point, exponent. */
function inNumber(c: number): boolean {
  return (c >= 48 && c <= 57) || c === 43 || c === 45 || c === 46 || c === 69 || c === 101;
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

/** A key token; its path is read from its frame (valid during the visit). */
class KeyToken {
  readonly kind = "key";
  constructor(
    private readonly frame: Frame,
    readonly key: string,
    readonly pos: number,
    readonly repeated: boolean,
  ) {}
  get path(): string {
    return childPath(this.frame);
  }
}

/** A number token; its path and literal are computed when read (valid during the visit). */
class NumberToken {
  readonly kind = "number";
  constructor(
    private readonly text: string,
    private readonly frame: Frame | undefined,
    readonly pos: number,
    readonly end: number,
  ) {}
  get path(): string {
    return this.frame === undefined ? "" : childPath(this.frame);
  }
  get literal(): string {
    return this.text.slice(this.pos, this.end);
  }
}

/** Visits the keys and number literals of the (valid) JSON `text`; see the header. */
export function walkJson<T>(text: string, visit: (token: JsonToken) => T | undefined): T | undefined {
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
        const raw = text.slice(i + 1, end - 1);
        const key = raw.includes("\\") ? (JSON.parse(text.slice(i, end)) as string) : raw;
        top.key = key;
        const repeated = top.keys.has(key);
        top.keys.add(key);
        expectKey = false;
        const r = visit(new KeyToken(top, key, i, repeated));
        if (r !== undefined) return r;
      }
      i = end;
    } else if (c === 45 || (c >= 48 && c <= 57)) {
      let end = i + 1;
      while (end < text.length && inNumber(text.charCodeAt(end))) end++;
      const r = visit(new NumberToken(text, top, i, end));
      if (r !== undefined) return r;
      i = end;
    } else i++;
  }
  return undefined;
}
