/**
 * How a refusal of input says what it was given, the same in every layer (the World's ChapgameError,
 * the scene's and the Timeline's SceneError): `given(v)` names the value ("-2", "NaN", "the string
 * \"1\"", "null", "an array of 3", "an object", "a function", "3n"), appended to the reason as " (got …)" (`refused`);
 * `quoteId(id)` writes an id as the messages quote it, in double quotes with JSON escapes
 * (`body "a"`), so that an id with spaces, quotes or nothing printable still reads unambiguously;
 * `unknownField(known)` is the reason a key no field has is refused with, the same by the World's
 * options and edits as by a scene file's objects: "unknown field (known: …)"; `frictionUnderGravity(mu)`
 * and `gravityWithFriction(ids)` are the reasons a non-zero gravity field is refused while bodies have friction, the same by the
 * World's edits as by a scene's actions: a body's mu > 0 under gravity, and gravity switched on under bodies with friction.
 */
import { ChapgameError } from "./errors.js";

/** A value as a refusal names it: "-2", "the string \"1\"", "null", "an array of 3", "an object". */
export function given(v: unknown): string {
  if (typeof v === "string") return `the string ${JSON.stringify(v.length > 40 ? `${v.slice(0, 40)}…` : v)}`;
  if (Array.isArray(v)) return `an array of ${v.length}`;
  if (typeof v === "object" && v !== null) return "an object";
  if (typeof v === "function") return "a function";
  if (typeof v === "bigint") return `${v}n`;
  return String(v);
}

/** An id as messages quote it: `"a"`. */
export function quoteId(id: string): string {
  return JSON.stringify(id);
}

/** The World's refusal of value v of field `path`: the reason, and what was given. */
export function refused(path: string, reason: string, v: unknown): ChapgameError {
  return new ChapgameError(path, `${reason} (got ${given(v)})`);
}

/** The reason a key that is no field of its object is refused with: "unknown field (known: a, b)",
 *  then `more` (a hint) inside the parentheses when given. */
export function unknownField(known: readonly string[], more = ""): string {
  return `unknown field (known: ${known.join(", ")}${more})`;
}

/**
 * The reason a friction coefficient mu > 0 is refused under a non-zero gravity field, the same by
 * the World's edits as by a scene's actions (the World said "must be 0 while the gravity field is
 * non-zero", a scene "friction (mu > 0) cannot be combined with …": review of session 26): the
 * rule, the value given and what to do.
 */
export function frictionUnderGravity(mu: unknown): string {
  return `friction (mu > 0) cannot be combined with a non-zero gravity field (got ${given(mu)}): set mu to 0, or the gravity field to [0, 0] first`;
}

/**
 * The reason a non-zero gravity field is refused while the bodies `ids` (sorted, at least one) have
 * mu > 0: every one of them named, the first ten and how many more, and what to do.
 */
export function gravityWithFriction(ids: readonly string[]): string {
  const shown = ids.slice(0, 10).map(quoteId).join(", ");
  const more = ids.length > 10 ? ` and ${ids.length - 10} more` : "";
  const which =
    ids.length === 1
      ? `body ${shown} has mu > 0: set its mu to 0 first`
      : `bodies ${shown}${more} have mu > 0: set their mu to 0 first`;
  return `a non-zero gravity field cannot be combined with friction (${which})`;
}
