/**
 * Field readers for scene validation: each reads one field of a plain object, checks it and returns
 * the normalized value, or throws SceneError naming the field's path and the reason.
 */
import { given, unknownField } from "../sim/refusalText.js";
import { SceneError } from "./errors.js";
import type { LineKind, Vec2 } from "./types.js";

export type Obj = Record<string, unknown>;

export function isObject(v: unknown): v is Obj {
  return typeof v === "object" && v !== null && !Array.isArray(v);
}

export function join(path: string, key: string): string {
  return path === "" ? key : `${path}.${key}`;
}

/** A refusal of value v of field `path`: the reason, and what was given (given: sim/refusalText.ts,
 *  shared with the World's refusals). */
export function refuse(path: string, reason: string, v: unknown): SceneError {
  return new SceneError(path, `${reason} (got ${given(v)})`);
}

function required(o: Obj, key: string, path: string): unknown {
  const v = o[key];
  if (v === undefined) throw new SceneError(join(path, key), "is required");
  return v;
}

/** Any finite number. */
export function finite(o: Obj, key: string, path: string): number {
  const v = required(o, key, path);
  if (typeof v !== "number" || !Number.isFinite(v))
    throw refuse(join(path, key), "must be a finite number", v);
  return v;
}

/** A finite number > 0 (radius). */
export function positive(o: Obj, key: string, path: string): number {
  const v = required(o, key, path);
  if (typeof v !== "number" || !Number.isFinite(v) || !(v > 0))
    throw refuse(join(path, key), "must be a positive finite number", v);
  return v;
}

/** A finite number >= 0 (time, mu, g). */
export function nonNegative(o: Obj, key: string, path: string): number {
  const v = required(o, key, path);
  if (typeof v !== "number" || !Number.isFinite(v) || !(v >= 0))
    throw refuse(join(path, key), "must be a non-negative finite number", v);
  return v === 0 ? 0 : v; // -0 becomes 0
}

/** A mass: a finite number > 0, or Infinity (written "Infinity" in JSON). A null says why: it is
 *  what JSON.stringify writes for Infinity (a toScene() saved without serializeScene). */
export function mass(o: Obj, key: string, path: string): number {
  const v = required(o, key, path);
  if (v === "Infinity" || v === Number.POSITIVE_INFINITY) return Number.POSITIVE_INFINITY;
  if (typeof v !== "number" || !Number.isFinite(v) || !(v > 0)) {
    const e = refuse(join(path, key), 'must be a positive finite number or "Infinity"', v);
    if (v !== null) throw e;
    throw new SceneError(
      e.path,
      `${e.reason}: JSON.stringify writes Infinity as null; serializeScene writes "Infinity"`,
    );
  }
  return v;
}

/** A non-negative integer up to Number.MAX_SAFE_INTEGER (event counts, as the CLI's --max-events:
 *  beyond it consecutive counts are no longer distinct doubles). */
export function count(o: Obj, key: string, path: string): number {
  const v = required(o, key, path);
  if (typeof v !== "number" || !Number.isInteger(v) || v < 0)
    throw refuse(join(path, key), "must be a non-negative integer", v);
  if (v > Number.MAX_SAFE_INTEGER)
    throw new SceneError(
      join(path, key),
      `must be a non-negative integer at most ${Number.MAX_SAFE_INTEGER} (got ${v})`,
    );
  return v;
}

/** `[x, y]` with both finite. */
export function vec2(o: Obj, key: string, path: string): Vec2 {
  const v = required(o, key, path);
  if (!Array.isArray(v) || v.length !== 2)
    throw refuse(join(path, key), "must be an array of two finite numbers", v);
  // a pair with one bad component names that component, as the World does (`v[1]`: audit of session 20)
  for (const k of [0, 1] as const) {
    const c: unknown = v[k];
    if (typeof c !== "number" || !Number.isFinite(c))
      throw refuse(`${join(path, key)}[${k}]`, "must be a finite number", c);
  }
  return [v[0], v[1]];
}

/** A non-empty string id. */
export function id(o: Obj, key: string, path: string): string {
  const v = required(o, key, path);
  if (typeof v !== "string" || v.length === 0) throw refuse(join(path, key), "must be a non-empty string", v);
  return v;
}

const LINE_KINDS: readonly LineKind[] = ["line", "ray", "segment"];

export function lineKind(o: Obj, key: string, path: string): LineKind {
  const v = required(o, key, path);
  if (typeof v !== "string" || !(LINE_KINDS as readonly string[]).includes(v))
    throw refuse(join(path, key), 'must be one of "line", "ray", "segment"', v);
  return v as LineKind;
}

/** Refuses any key of `o` not in `allowed`; the message lists the known ones. */
export function onlyKeys(o: Obj, allowed: readonly string[], path: string): void {
  for (const k of Object.keys(o))
    if (!allowed.includes(k)) throw new SceneError(join(path, k), unknownFieldReason(k, allowed));
}

/** "unknown field (known: ...)", with the scene format's spelling of a velocity when that is the slip. */
function unknownFieldReason(k: string, allowed: readonly string[]): string {
  const hint = (k === "vx" || k === "vy") && allowed.includes("v") ? "; a velocity is v: [vx, vy]" : "";
  return unknownField(allowed, hint);
}
