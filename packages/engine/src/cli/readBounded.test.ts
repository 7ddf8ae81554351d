// readBounded: a source read in chunks, refused as soon as its text passes the limit (an endless
// device such as /dev/zero included), counting characters as a string holds them.
import { describe, expect, it } from "vitest";
import { readBounded, STRING_MAX_CHARS, TooLongError, utf16Units } from "./readBounded.js";

/** A source of `bytes` given `per` bytes a read at most; `reads` counts the reads. */
function source(bytes: Uint8Array, per = 3) {
  let at = 0;
  const s = {
    reads: 0,
    read: (buffer: Uint8Array) => {
      s.reads++;
      const n = Math.min(per, bytes.length - at, buffer.length);
      buffer.set(bytes.subarray(at, at + n));
      at += n;
      return n;
    },
  };
  return s;
}

/** An endless source of zero bytes (/dev/zero): `chunk` bytes each read. */
function endless(chunk: number) {
  const s = {
    bytes: 0,
    read: (buffer: Uint8Array) => {
      const n = Math.min(chunk, buffer.length);
      buffer.fill(0, 0, n);
      s.bytes += n;
      return n;
    },
  };
  return s;
}

describe("readBounded", () => {
  it("reads a source to its end, in any chunks, and tells the bytes read so far", () => {
    const text = new TextEncoder().encode('{"a": "café 🎱"}');
    const s = source(text, 4);
    const seen: number[] = [];
    expect(readBounded(s.read, (b) => seen.push(b))).toEqual(text);
    expect(seen.at(-1)).toBe(text.length);
    expect(seen).toEqual([...seen].sort((a, b) => a - b));
    expect(readBounded(source(new Uint8Array(0)).read)).toEqual(new Uint8Array(0));
  });

  it("an endless source (/dev/zero) is refused as soon as its text passes the limit, not read for ever", () => {
    // Review of session 31: `chapgame check /dev/zero` never returned.
    const zero = endless(1000);
    expect(() => readBounded(zero.read, () => {}, 10_000)).toThrow(TooLongError);
    expect(zero.bytes).toBe(11_000); // the first read past the limit
    const e = (() => {
      try {
        readBounded(endless(1000).read, () => {}, 10_000);
      } catch (x) {
        return x as TooLongError;
      }
    })();
    expect(e?.code).toBe("ERR_STRING_TOO_LONG");
    expect(STRING_MAX_CHARS).toBe(0x1fffffe8);
  });

  it("bytes past the limit that are fewer characters (multi-byte UTF-8) are still read: only characters count", () => {
    const e = new TextEncoder().encode("é".repeat(6)); // 12 bytes, 6 characters
    expect(readBounded(source(e).read, () => {}, 8)).toEqual(e);
    expect(() => readBounded(source(e).read, () => {}, 5)).toThrow(TooLongError);
  });

  it("utf16Units counts as a string holds the text: a four-byte character is two", () => {
    for (const t of ["", "abc", "café", "🎱", "a🎱é€"])
      expect(utf16Units(new TextEncoder().encode(t)), t).toBe(t.length);
  });
});
