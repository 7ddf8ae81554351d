/**
 * Number literals of a JSON text that a double cannot hold (pure). JSON.parse reads a literal beyond
 * the largest double (1e999) as Infinity and one below the smallest (1e-999) as 0, without a word;
 * a scene file writes an infinite mass as the string "Infinity", so `"m": 1e999` must not pass for
 * one. `unrepresentableNumbers(text)` scans a text JSON.parse has already accepted and returns the
 * first literal that overflows (to Infinity or -Infinity), with its path (`actions[0].m`), line and
 * column, or null; and every literal with a non-zero digit that reads as 0 or -0, by path (to
 * explain a refusal of that field: `r` must be > 0). Linear; no recursion (jsonPaths.ts walks it).
 */
import { type JsonToken, lineColumn, walkJson } from "./jsonPaths.js";

export interface NumberLiteral {
  /** Path of the value, e.g. `actions[0].m` or `actions[0].v[1]`. */
  readonly path: string;
  /** The literal as written, e.g. `1e999`. */
  readonly literal: string;
  /** 1-based line and column of its first character. */
  readonly line: number;
  readonly column: number;
}

/** Longest literal without an exponent that cannot be out of range (beyond ~1.8e308 takes 309 digits, a
 *  non-zero value below ~2.5e-324 takes a 324-place fraction). */
const SHORT = 300;

export function unrepresentableNumbers(text: string): {
  overflow: NumberLiteral | null;
  underflow: Map<string, string>;
} {
  const underflow = new Map<string, string>();
  const overflow = walkJson(text, (t) => overflowOf(text, t, underflow));
  return { overflow: overflow ?? null, underflow };
}

/** One token of walkJson: the literal if it overflows; one that underflows is added to `underflow`
 *  (path to literal). For a walk that also looks for other things (parse.ts). */
export function overflowOf(
  text: string,
  t: JsonToken,
  underflow: Map<string, string>,
): NumberLiteral | undefined {
  if (t.kind !== "number") return undefined;
  // only an exponent or a very long literal can leave the range of a double
  if (t.end - t.pos <= SHORT && !hasExponent(text, t.pos, t.end)) return undefined;
  const lit = t.literal;
  const v = Number(lit);
  if (!Number.isFinite(v)) return { path: t.path, literal: lit, ...lineColumn(text, t.pos) };
  if (v === 0 && /[1-9]/.test(lit.split(/[eE]/)[0] as string)) underflow.set(t.path, lit);
  return undefined;
}

function hasExponent(text: string, from: number, to: number): boolean {
  for (let i = from; i < to; i++) {
    const c = text.charCodeAt(i);
    if (c === 101 || c === 69) return true;
  }
  return false;
}
