import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { decodeUtf8, firstInvalidUtf8 } from "./utf8.js";

const bytes = (...b: number[]) => new Uint8Array(b);
const utf8 = (s: string) => new TextEncoder().encode(s);

describe("decodeUtf8: a scene file's bytes, refusing what is not UTF-8", () => {
  it("decodes UTF-8 as Node does, a leading byte order mark kept (parseScene skips it)", () => {
    const text = '\uFEFF{"id": "café ☕ 𝄞"}\r\n';
    expect(decodeUtf8(utf8(text))).toBe(text);
    expect(decodeUtf8(bytes())).toBe("");
  });

  it("refuses a Latin-1 byte, naming it, its line and its column (it became U+FFFD silently)", () => {
    const latin1 = bytes(...utf8('{\n  "id": "caf'), 0xe9, ...utf8('"\n}'));
    expect(() => decodeUtf8(latin1)).toThrow(
      "not UTF-8 text: byte 0xE9 at line 2, column 13 (save the file as UTF-8)",
    );
    // a UTF-16 file's byte order mark
    expect(() => decodeUtf8(bytes(0xff, 0xfe, 0x7b, 0x00))).toThrow("byte 0xFF at line 1, column 1");
  });

  it("finds the first invalid byte by the WHATWG rules", () => {
    expect(firstInvalidUtf8(utf8("aé☕𝄞"))).toBe(-1);
    expect(firstInvalidUtf8(bytes(0x61, 0x80))).toBe(1); // a lone continuation byte
    expect(firstInvalidUtf8(bytes(0xc0, 0xaf))).toBe(0); // overlong
    expect(firstInvalidUtf8(bytes(0xe0, 0x80, 0xaf))).toBe(0); // overlong
    expect(firstInvalidUtf8(bytes(0xed, 0xa0, 0x80))).toBe(0); // a surrogate
    expect(firstInvalidUtf8(bytes(0xf4, 0x90, 0x80, 0x80))).toBe(0); // above U+10FFFF
    expect(firstInvalidUtf8(bytes(0x61, 0xe2, 0x98))).toBe(1); // cut short
    expect(firstInvalidUtf8(bytes(0xf5))).toBe(0);
  });

  it("refuses exactly the byte strings firstInvalidUtf8 finds a bad byte in (the native decoder decides first)", () => {
    // bytes around the UTF-8 boundaries (lead bytes, continuation ranges, surrogates, > U+10FFFF)
    const byte = fc.oneof(
      fc.integer({ min: 0x00, max: 0x7f }),
      fc.integer({ min: 0x80, max: 0xbf }),
      fc.constantFrom(
        0xc0,
        0xc1,
        0xc2,
        0xdf,
        0xe0,
        0xed,
        0xef,
        0xf0,
        0xf4,
        0xf5,
        0xff,
        0x9f,
        0xa0,
        0x8f,
        0x90,
      ),
    );
    fc.assert(
      fc.property(fc.array(byte, { maxLength: 12 }), (list) => {
        const b = new Uint8Array(list);
        const bad = firstInvalidUtf8(b);
        if (bad < 0) expect(decodeUtf8(b)).toBe(new TextDecoder("utf-8", { ignoreBOM: true }).decode(b));
        else expect(() => decodeUtf8(b)).toThrow(/^not UTF-8 text: byte 0x/);
      }),
      { seed: seedFor("decodeUtf8 agrees with firstInvalidUtf8"), numRuns: 2000 },
    );
  });
});
