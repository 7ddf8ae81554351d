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

/** An open object or array. Frames are reused by depth (the walk allocates none per value). */
interface Frame {
  /** false for an array */
  isObject: boolean;
  /** The object's keys seen so far (a Set once there are many, else the array). */
  keys: string[];
  keySet: Set<string> | null;
  /** The array's next element index, or the object's last key. */
  index: number;
  key: string;
}

/** Keys an object may have before its repeats are looked up in a Set instead of its key list. */
const FEW_KEYS = 16;

/** Whether `key` repeats a key of `frame` seen before; records it. */
function seen(frame: Frame, key: string): boolean {
  if (frame.keySet !== null) {
    if (frame.keySet.has(key)) return true;
    frame.keySet.add(key);
    return false;
  }
  const keys = frame.keys;
  for (let k = 0; k < keys.length; k++) if (keys[k] === key) return true;
  keys.push(key);
  if (keys.length > FEW_KEYS) frame.keySet = new Set(keys);
  return false;
}

/** The path of the current child of `stack[depth]` (the value being read), built from the frames
 *  from the top level down (valid while the walk stands where it is). */
function pathAt(stack: readonly Frame[], depth: number): string {
  let path = "";
  for (let d = 0; d <= depth; d++) {
    const f = stack[d] as Frame;
    if (!f.isObject) path = `${path}[${f.index}]`;
    else path = path === "" ? f.key : `${path}.${f.key}`;
  }
  return path;
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

/** A key token; its path is read from the frames (valid during the visit). */
class KeyToken {
  readonly kind = "key";
  constructor(
    private readonly stack: readonly Frame[],
    private readonly depth: number,
    readonly key: string,
    readonly pos: number,
    readonly repeated: boolean,
  ) {}
  get path(): string {
    return pathAt(this.stack, this.depth);
  }
}

/** A number token; its path and literal are computed when read (valid during the visit). */
class NumberToken {
  readonly kind = "number";
  constructor(
    private readonly text: string,
    private readonly stack: readonly Frame[],
    private readonly depth: number,
    readonly pos: number,
    readonly end: number,
  ) {}
  get path(): string {
    return this.depth < 0 ? "" : pathAt(this.stack, this.depth);
  }
  get literal(): string {
    return this.text.slice(this.pos, this.end);
  }
}

/** Visits the keys and number literals of the (valid) JSON `text`; see the header. */
export function walkJson<T>(text: string, visit: (token: JsonToken) => T | undefined): T | undefined {
  const stack: Frame[] = [];
  let depth = -1; // stack[depth] is the innermost open value
  let top: Frame | undefined;
  // Whether the next string in the innermost object is a key (after `{` or `,`).
  let expectKey = false;
  let i = 0;
  const n = text.length;
  while (i < n) {
    const c = text.charCodeAt(i);
    if (c === 32 || c === 58 || c === 10 || c === 13 || c === 9) i++;
    else if (c === 44) {
      // `,`: the next key of an object, or the next element of an array.
      if (top !== undefined && !top.isObject) top.index++;
      expectKey = top?.isObject === true;
      i++;
    } else if (c === 34) {
      const end = stringEnd(text, i);
      if (expectKey && top !== undefined) {
        const raw = text.slice(i + 1, end - 1);
        const key = raw.includes("\\") ? (JSON.parse(text.slice(i, end)) as string) : raw;
        top.key = key;
        const repeated = seen(top, key);
        expectKey = false;
        const r = visit(new KeyToken(stack, depth, key, i, repeated));
        if (r !== undefined) return r;
      }
      i = end;
    } else if (c === 45 || (c >= 48 && c <= 57)) {
      let end = i + 1;
      while (end < n && inNumber(text.charCodeAt(end))) end++;
      const r = visit(new NumberToken(text, stack, depth, i, end));
      if (r !== undefined) return r;
      i = end;
    } else if (c === 123 || c === 91) {
      // `{` or `[`: a value starting (its path is the enclosing frames' current children)
      depth++;
      let f = stack[depth];
      if (f === undefined) {
        f = { isObject: false, keys: [], keySet: null, index: 0, key: "" };
        stack.push(f);
      }
      f.isObject = c === 123;
      f.keys.length = 0;
      f.keySet = null;
      f.index = 0;
      f.key = "";
      top = f;
      expectKey = f.isObject;
      i++;
    } else if (c === 125 || c === 93) {
      depth--;
      top = depth < 0 ? undefined : stack[depth];
      expectKey = false;
      i++;
    } else i++;
  }
  return undefined;
}
