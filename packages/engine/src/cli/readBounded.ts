/**
 * readBounded(read, progress, limit): all the bytes of a source read in chunks (pure: `read` is the
 * bin's fs.readSync on the source's descriptor), refusing a source whose text would pass `limit`
 * characters (by default STRING_MAX_CHARS, the most a JavaScript string holds) as soon as it does,
 * with a TooLongError. A device or a fifo that never ends (/dev/zero, /dev/urandom, `yes |`) is
 * refused there after one bounded read instead of being read for ever; a regular file larger than
 * that too, without decoding it. `progress` is told the bytes read so far after each chunk (the CLI
 * shows them on long reads: progress.ts).
 * Characters are counted as UTF-16 code units, as a string holds them: a byte that starts a UTF-8
 * sequence is one, a four-byte sequence's first byte two; continuation bytes none. Until the bytes
 * pass the limit they cannot be more characters than that, so the bytes are counted only then.
 */

/** The most characters (UTF-16 code units) a V8 string holds: 0x1fffffe8 (Node's
 *  buffer.constants.MAX_STRING_LENGTH on 64-bit hosts). */
export const STRING_MAX_CHARS = 0x1fffffe8;

/** Bytes asked of the source at each read. */
const CHUNK_BYTES = 1 << 20;

/** Thrown when the source's text passes the limit; `code` as Node's own error for a string too long. */
export class TooLongError extends Error {
  readonly code = "ERR_STRING_TOO_LONG";
  constructor(readonly limit: number) {
    super(`more than ${limit} characters`);
    this.name = "TooLongError";
  }
}

/** The UTF-16 code units the UTF-8 `bytes` decode to (see the header). */
export function utf16Units(bytes: Uint8Array): number {
  let units = 0;
  for (let i = 0; i < bytes.length; i++) {
    const b = bytes[i] as number;
    if ((b & 0xc0) !== 0x80) units += b >= 0xf0 ? 2 : 1;
  }
  return units;
}

/**
 * The source's bytes: `read(buffer)` fills the start of `buffer` and returns how many bytes it put
 * there (0 at the end). Throws TooLongError as soon as the text passes `limit` characters.
 */
export function readBounded(
  read: (buffer: Uint8Array) => number,
  progress: (bytes: number) => void = () => {},
  limit: number = STRING_MAX_CHARS,
): Uint8Array {
  const chunks: Uint8Array[] = [];
  let bytes = 0;
  let units = -1; // counted once the bytes pass the limit
  for (;;) {
    const buffer = new Uint8Array(CHUNK_BYTES);
    const n = read(buffer);
    if (n === 0) break;
    const chunk = buffer.subarray(0, n);
    chunks.push(chunk);
    bytes += n;
    if (bytes > limit) {
      units = units < 0 ? chunks.reduce((sum, c) => sum + utf16Units(c), 0) : units + utf16Units(chunk);
      if (units > limit) throw new TooLongError(limit);
    }
    progress(bytes);
  }
  if (chunks.length === 1) return chunks[0] as Uint8Array;
  const all = new Uint8Array(bytes);
  let at = 0;
  for (const c of chunks) {
    all.set(c, at);
    at += c.length;
  }
  return all;
}
