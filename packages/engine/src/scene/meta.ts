/**
 * checkMeta(value): a scene's `meta` (free data for tools, kept as it is) must be plain JSON data
 * that JSON carries exactly, nested at most META_MAX_DEPTH levels; a refusal is a SceneError naming
 * the value's path (`meta.n`, `meta.a[1]`).
 *
 * - An object at the top. Inside: null, booleans, strings, finite numbers other than -0, arrays
 *   without empty slots or extra keys, and plain objects (prototype Object.prototype or null)
 *   without symbol keys. Everything else JSON.stringify would write as something else or not at
 *   all: a BigInt threw a raw TypeError, NaN and ±Infinity became null, functions, undefined and
 *   symbols vanished, -0 came back as 0, a Date became a string and a Map {} (audit of session 19).
 *   parseScene refuses -0 read from a file too (JSON text can hold "-0"), so that what parseScene
 *   accepts serializeScene writes back unchanged.
 * - Depth: JSON.parse reads any depth, but writing it back (JSON.stringify in toScene and
 *   serializeScene) recurses, and 10,000 levels overflowed the stack: an internal error instead of
 *   a message naming the field. The walk here is iterative.
 */
import { SceneError } from "./errors.js";
import { isObject, refuse } from "./fields.js";

/** Deepest nesting of objects and arrays accepted in `meta` (meta itself is level 1). */
export const META_MAX_DEPTH = 100;

const DATA = "must be JSON data (null, a boolean, a finite number, a string, an array or an object)";

export function checkMeta(value: unknown): asserts value is Record<string, unknown> {
  if (!isObject(value)) throw refuse("meta", "must be an object", value);
  const stack: [unknown, number, string, Enclosing | null][] = [[value, 1, "meta", null]];
  while (stack.length > 0) {
    const [v, depth, path, up] = stack.pop() as [unknown, number, string, Enclosing | null];
    if (v === null || typeof v === "string" || typeof v === "boolean") continue;
    if (typeof v === "number") {
      if (!Number.isFinite(v))
        throw new SceneError(path, `must be a finite number (got ${v}): JSON has no NaN or Infinity`);
      if (Object.is(v, -0))
        throw new SceneError(path, "must not be -0: JSON.stringify writes it as 0 (write 0)");
      continue;
    }
    if (typeof v === "bigint")
      throw new SceneError(
        path,
        `must be a number, not a BigInt (got ${v}n): JSON has no BigInt (write it as a string)`,
      );
    if (typeof v !== "object")
      throw new SceneError(path, `${DATA}, not ${typeof v}: JSON.stringify drops it`);
    if (depth > META_MAX_DEPTH) throw tooDeep(v, path, up);
    const here: Enclosing = { value: v, path, up };
    if (Object.getOwnPropertySymbols(v).length > 0)
      throw new SceneError(path, "must not have symbol keys: JSON.stringify drops them");
    if (Array.isArray(v)) {
      for (let i = 0; i < v.length; i++) {
        if (!(i in v))
          throw new SceneError(`${path}[${i}]`, "must not be an empty slot: JSON writes it as null");
      }
      if (Object.keys(v).length !== v.length)
        throw new SceneError(path, "must be an array without other keys: JSON.stringify drops them");
      for (let i = v.length - 1; i >= 0; i--) stack.push([v[i], depth + 1, `${path}[${i}]`, here]);
      continue;
    }
    const proto = Object.getPrototypeOf(v);
    if (proto !== Object.prototype && proto !== null)
      throw new SceneError(
        path,
        `must be a plain object or an array (got ${constructorName(v)}): JSON would not keep it as it is`,
      );
    const keys = Object.keys(v);
    for (let i = keys.length - 1; i >= 0; i--) {
      const k = keys[i] as string;
      stack.push([(v as Record<string, unknown>)[k], depth + 1, `${path}.${k}`, here]);
    }
  }
}

/** An object or array that holds the value being checked, and the one that holds it. */
interface Enclosing {
  value: unknown;
  path: string;
  up: Enclosing | null;
}

/** The refusal of a value nested past META_MAX_DEPTH: a cycle (an object that holds itself, which
 *  JSON cannot write at all) is named as one, with the path back; otherwise where the limit is passed
 *  (both said only `meta: must not be nested deeper than 100 levels`: review of session 31). */
function tooDeep(v: unknown, path: string, up: Enclosing | null): SceneError {
  const limit = `must not be nested deeper than ${META_MAX_DEPTH} levels`;
  // the paths at which v recurs, innermost first: the outermost is where the cycle starts
  const at = [path];
  for (let e = up; e !== null; e = e.up) if (e.value === v) at.push(e.path);
  if (at.length > 1)
    return new SceneError(
      "meta",
      `${limit} (got a cycle: ${shortPath(at[at.length - 2] as string)} is ${shortPath(at[at.length - 1] as string)} again, which JSON cannot write)`,
    );
  return new SceneError("meta", `${limit} (got level ${META_MAX_DEPTH + 1} at ${shortPath(path)})`);
}

/** A path of at most 120 characters, its middle left out. */
function shortPath(path: string): string {
  return path.length <= 120 ? path : `${path.slice(0, 60)}…${path.slice(-59)}`;
}

/** The name of an object's class, for a message ("a Date"). */
function constructorName(v: object): string {
  const c = (v as { constructor?: { name?: unknown } }).constructor;
  return typeof c?.name === "string" && c.name !== "" ? `a ${c.name}` : "an object with a prototype";
}
