/**
 * Where a JSON text breaks the grammar (pure). V8's JSON.parse gives a position for some errors
 * ("... in JSON at position 8") and none for others ("Unexpected token 'N', ... is not valid JSON",
 * the message a scene with `NaN` in it gets), so the scene reader locates every error itself:
 * `jsonErrorOffset` returns the index of the first character that cannot continue a JSON text
 * (RFC 8259), `text.length` when the text stops before it is complete, or -1 when the text is
 * valid. Linear in the text; no recursion, so deep nesting cannot overflow the stack.
 */

const VALUE = 0;
const VALUE_OR_CLOSE = 1;
const KEY = 2;
const KEY_OR_CLOSE = 3;
const AFTER_VALUE = 4;
const OBJECT = 0;
const ARRAY = 1;

/** Error results of the token scanners are encoded as -(offset + 1), so that 0 stays an offset. */
const fail = (offset: number): number => -offset - 1;

function isDigit(c: number): boolean {
  return c >= 48 && c <= 57;
}

function isHex(c: number): boolean {
  return isDigit(c) || (c >= 65 && c <= 70) || (c >= 97 && c <= 102);
}

/** End (exclusive) of the string starting at the quote at i, or fail(offset of the fault). */
function scanString(text: string, i: number): number {
  let j = i + 1;
  for (;;) {
    if (j >= text.length) return fail(text.length);
    const c = text.charCodeAt(j);
    if (c === 34) return j + 1;
    if (c < 0x20) return fail(j);
    if (c !== 92) {
      j++;
      continue;
    }
    const e = text.charCodeAt(j + 1);
    if (j + 1 >= text.length) return fail(text.length);
    if (e === 117) {
      for (let k = j + 2; k < j + 6; k++) {
        if (k >= text.length) return fail(text.length);
        if (!isHex(text.charCodeAt(k))) return fail(k);
      }
      j += 6;
    } else if ('"\\/bfnrt'.includes(text.charAt(j + 1))) j += 2;
    else return fail(j + 1);
  }
}

/** End of the digits starting at j (at least one), or fail. */
function digits(text: string, j: number): number {
  if (j >= text.length) return fail(text.length);
  if (!isDigit(text.charCodeAt(j))) return fail(j);
  while (j < text.length && isDigit(text.charCodeAt(j))) j++;
  return j;
}

/** End (exclusive) of the number starting at i, or fail(offset of the fault). */
function scanNumber(text: string, i: number): number {
  let j = i;
  if (text.charCodeAt(j) === 45) j++;
  if (j < text.length && text.charCodeAt(j) === 48) j++;
  else {
    j = digits(text, j);
    if (j < 0) return j;
  }
  if (j < text.length && text.charCodeAt(j) === 46) {
    j = digits(text, j + 1);
    if (j < 0) return j;
  }
  const e = text.charCodeAt(j);
  if (j < text.length && (e === 101 || e === 69)) {
    j++;
    const sign = text.charCodeAt(j);
    if (j < text.length && (sign === 43 || sign === 45)) j++;
    j = digits(text, j);
  }
  return j;
}

/** End of the literal `word` at i, or fail(offset of its first wrong character). */
function scanLiteral(text: string, i: number, word: string): number {
  for (let k = 0; k < word.length; k++) {
    if (i + k >= text.length) return fail(text.length);
    if (text.charCodeAt(i + k) !== word.charCodeAt(k)) return fail(i + k);
  }
  return i + word.length;
}

/** The start of a value at i: its end, or fail; containers are opened on `stack`. */
function scanValueStart(text: string, i: number, stack: number[]): number {
  const c = text.charCodeAt(i);
  if (c === 123 || c === 91) {
    stack.push(c === 123 ? OBJECT : ARRAY);
    return i + 1;
  }
  if (c === 34) return scanString(text, i);
  if (c === 45 || isDigit(c)) return scanNumber(text, i);
  if (c === 116) return scanLiteral(text, i, "true");
  if (c === 102) return scanLiteral(text, i, "false");
  if (c === 110) return scanLiteral(text, i, "null");
  return fail(i);
}

/** Index of the first character where `text` stops being JSON, text.length if it ends early, -1 if valid. */
export function jsonErrorOffset(text: string): number {
  const n = text.length;
  const stack: number[] = [];
  let state = VALUE;
  let i = 0;
  for (;;) {
    while (i < n) {
      const c = text.charCodeAt(i);
      if (c !== 32 && c !== 9 && c !== 10 && c !== 13) break;
      i++;
    }
    if (i >= n) return state === AFTER_VALUE && stack.length === 0 ? -1 : n;
    const c = text.charCodeAt(i);
    if (state === AFTER_VALUE) {
      const top = stack[stack.length - 1];
      if (top === undefined) return i;
      if (c === 44) state = top === OBJECT ? KEY : VALUE;
      else if (c === (top === OBJECT ? 125 : 93)) stack.pop();
      else return i;
      i++;
      continue;
    }
    if ((state === KEY_OR_CLOSE && c === 125) || (state === VALUE_OR_CLOSE && c === 93)) {
      stack.pop();
      state = AFTER_VALUE;
      i++;
      continue;
    }
    if (state === KEY || state === KEY_OR_CLOSE) {
      if (c !== 34) return i;
      const end = scanString(text, i);
      if (end < 0) return -end - 1;
      i = end;
      while (i < n && " \t\n\r".includes(text.charAt(i))) i++;
      if (i >= n) return n;
      if (text.charCodeAt(i) !== 58) return i;
      i++;
      state = VALUE;
      continue;
    }
    const depth = stack.length;
    const end = scanValueStart(text, i, stack);
    if (end < 0) return -end - 1;
    i = end;
    if (stack.length > depth) state = stack[depth] === OBJECT ? KEY_OR_CLOSE : VALUE_OR_CLOSE;
    else state = AFTER_VALUE;
  }
}
