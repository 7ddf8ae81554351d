/**
 * decodeUtf8(bytes): a scene file's bytes as text, refusing bytes that are not UTF-8 (pure).
 * Node's readFileSync(path, "utf8") turns each invalid byte into U+FFFD silently, so a file saved in
 * another encoding (Latin-1, UTF-16) read with ids changed ("café" in Latin-1 became "caf\uFFFD", and
 * two such ids could become one). Refused instead, naming where: the byte's line and column.
 */
import { lineColumn } from "../scene/jsonPaths.js";

/** The index of the first byte of `bytes` that does not continue valid UTF-8, or -1 (WHATWG rules:
 *  no overlong forms, no surrogates, nothing above U+10FFFF). */
export function firstInvalidUtf8(bytes: Uint8Array): number {
  const n = bytes.length;
  let i = 0;
  while (i < n) {
    const b = bytes[i] as number;
    if (b < 0x80) {
      i++;
      continue;
    }
    let need: number;
    let lo = 0x80;
    let hi = 0xbf;
    if (b >= 0xc2 && b <= 0xdf) need = 1;
    else if (b >= 0xe0 && b <= 0xef) {
      need = 2;
      if (b === 0xe0) lo = 0xa0;
      else if (b === 0xed) hi = 0x9f;
    } else if (b >= 0xf0 && b <= 0xf4) {
      need = 3;
      if (b === 0xf0) lo = 0x90;
      else if (b === 0xf4) hi = 0x8f;
    } else return i;
    for (let k = 1; k <= need; k++) {
      const c = bytes[i + k];
      if (c === undefined || c < (k === 1 ? lo : 0x80) || c > (k === 1 ? hi : 0xbf)) return i;
    }
    i += need + 1;
  }
  return -1;
}

/** Thrown for bytes that are not UTF-8; the message says where. */
export class NotUtf8Error extends Error {
  constructor(message: string) {
    super(message);
    this.name = "NotUtf8Error";
  }
}

interface Decoder {
  decode(bytes: Uint8Array): string;
}
type DecoderClass = new (label: string, options: { ignoreBOM: boolean; fatal?: boolean }) => Decoder;

/** The text of `bytes` (UTF-8; a leading byte order mark is kept for parseScene, which skips it), or
 *  a NotUtf8Error naming the first invalid byte, its line and its column (as the scene errors count
 *  them: lineColumn). */
export function decodeUtf8(bytes: Uint8Array): string {
  const { TextDecoder } = globalThis as unknown as { TextDecoder: DecoderClass };
  // The native decoder refuses what firstInvalidUtf8 refuses (the same WHATWG rules) but says not
  // where; the byte loop runs only then (it took 0.4 s on a 150 MB scene that was valid).
  try {
    return new TextDecoder("utf-8", { ignoreBOM: true, fatal: true }).decode(bytes);
  } catch (e) {
    // more text than a string holds (ERR_STRING_TOO_LONG): no second pass can read it either
    if ((e as { code?: unknown }).code === "ERR_STRING_TOO_LONG") throw e;
    // not UTF-8: find where below
  }
  const decoder = new TextDecoder("utf-8", { ignoreBOM: true });
  const bad = firstInvalidUtf8(bytes);
  if (bad < 0) return decoder.decode(bytes);
  const before = decoder.decode(bytes.subarray(0, bad));
  const { line, column } = lineColumn(before, before.length);
  const hex = (bytes[bad] as number).toString(16).toUpperCase().padStart(2, "0");
  throw new NotUtf8Error(
    `not UTF-8 text: byte 0x${hex} at line ${line}, column ${column} (save the file as UTF-8)`,
  );
}
