/**
 * The refusal of text typed in a field or a table cell, in the form of the engine's refusals
 * (packages/engine/src/sim/refusalText.ts): `label: reason (got …)`, then `: explanation` when one
 * is given (as the engine's "g: must be 0 or at least 1e-30 in size (got 1e-31): …"). What was typed
 * is named as the engine names a value: a number as written (`(got -3)`, `(got 1e400)`, `(got ∞)`),
 * other text quoted with JSON escapes (`(got "abc")`, `(got "")`), cut after 40 characters as the
 * engine cuts a string. The editor's messages said `, got "-3"` where the engine's said `(got -3)`:
 * the author read two styles side by side. Pure.
 */
import { parseNumber } from "./EditableCell";

/** Longest typed text quoted whole (the engine's `given` cuts a string there too). */
const QUOTED_MAX = 40;

/** What was typed, as a refusal names it: `-3` for a number, `"abc"` for other text. */
export function typedGiven(text: string): string {
  const t = text.trim();
  if (parseNumber(t) !== null) return t;
  return JSON.stringify(t.length > QUOTED_MAX ? `${t.slice(0, QUOTED_MAX)}…` : t);
}

/** `label: reason (got typed)`, then `: why` when given. */
export function refusedTyped(label: string, reason: string, text: string, why?: string): string {
  return `${label}: ${reason} (got ${typedGiven(text)})${why === undefined ? "" : `: ${why}`}`;
}

/** The refusal of a cell or field whose text is not a number. */
export function notANumber(label: string, text: string): string {
  return refusedTyped(label, "must be a number", text);
}
