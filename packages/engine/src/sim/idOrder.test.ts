// idOrder.ts: the keys never contradict the string order, and idBefore is exactly `<` on strings.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { idBefore, idOrderKey } from "./idOrder.js";

const SEED = Number(process.env.FC_SEED ?? 20261123);

/** Ids from a small alphabet (many shared prefixes and prefixes of each other), with odd characters. */
const id = fc.oneof(
  fc.string({ unit: fc.constantFrom("a", "b", "0", "9", "-", "~", "\u007f"), maxLength: 10 }),
  fc.string({ unit: fc.constantFrom("a", "\u0000", "\u0080", "é", "\ud83d", "\ude00"), maxLength: 9 }),
  fc.string({ maxLength: 12 }),
);

describe("id order keys", () => {
  it("a smaller key means a smaller id, and idBefore agrees with < on strings", () => {
    console.log(`[id order] fast-check seed ${SEED} (set FC_SEED to change)`);
    fc.assert(
      fc.property(id, id, (a, b) => {
        const ka = idOrderKey(a);
        const kb = idOrderKey(b);
        if (ka < kb) expect(a < b).toBe(true);
        if (ka > kb) expect(b < a).toBe(true);
        expect(idBefore(ka, kb, a, b)).toBe(a < b);
      }),
      { seed: SEED, numRuns: 20000 },
    );
  });

  it("decides ordinary ids by their keys alone, and leaves ties and odd characters to the strings", () => {
    expect(idOrderKey("d000123")).toBeLessThan(idOrderKey("d000124"));
    expect(idOrderKey("ab")).toBeLessThan(idOrderKey("abc"));
    expect(idOrderKey("")).toBe(0);
    expect(idOrderKey("ball-0001")).toBe(idOrderKey("ball-0002")); // a shared 7-character prefix
    expect(idOrderKey("a\u0000")).toBe(idOrderKey("a")); // a tie: the strings decide
    expect(idOrderKey("é")).toBeNaN();
    expect(idOrderKey("abcdefgé")).not.toBeNaN(); // beyond the 7th character: not read
    expect(idOrderKey("\u007f".repeat(7))).toBe(2 ** 49 - 1);
    expect(idBefore(Number.NaN, 5, "b", "a")).toBe(false);
    expect(idBefore(Number.NaN, 5, "a", "b")).toBe(true);
  });
});
