/**
 * The canonical order of body ids (UTF-16 code-unit order, as `<` on strings), decided from a number
 * per id when it can be. The response orders the two bodies of every collision by id, and comparing
 * the strings reads both ids' characters: at 10^5 bodies, two cache misses per collision. A key
 * packs an id's first 7 characters (each 1..127) as base-128 digits, padded with 0; keys in a
 * Float64Array are read from memory the pair already touches. Exact: integers below 2^49.
 *
 * If idOrderKey(a) < idOrderKey(b) then a < b: at the first differing digit, a's is either a
 * smaller character than b's or the padding under a character of b (a is then a proper prefix of
 * b). A character 0 reads as the padding, which can only make keys tie. Equal keys (a shared
 * 7-character prefix) and NaN keys (a character above 127 among the first 7) decide nothing:
 * `idBefore` then compares the strings.
 */

/** Characters packed into a key: 7 base-128 digits stay below 2^49, exact in a double. */
const KEY_CHARS = 7;

/** The order key of `id` (NaN when a character among its first 7 is above 127). */
export function idOrderKey(id: string): number {
  let key = 0;
  for (let i = 0; i < KEY_CHARS; i++) {
    const c = i < id.length ? id.charCodeAt(i) : 0;
    if (c > 127) return Number.NaN;
    key = key * 128 + c;
  }
  return key;
}

/** Whether id a sorts before id b, given their keys (the strings are compared only when the keys tie). */
export function idBefore(keyA: number, keyB: number, a: string, b: string): boolean {
  return keyA < keyB || (!(keyA > keyB) && a < b);
}
