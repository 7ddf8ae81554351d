/**
 * checkMeta(value): a scene's `meta` (free data for tools, kept as it is) must be a JSON object,
 * nested at most META_MAX_DEPTH levels. JSON.parse reads any depth, but writing it back
 * (JSON.stringify in toScene and serializeScene) recurses, and 10,000 levels overflowed the stack:
 * an internal error instead of a message naming the field. The walk here is iterative.
 */
import { SceneError } from "./errors.js";
import { isObject } from "./fields.js";

/** Deepest nesting of objects and arrays accepted in `meta` (meta itself is level 1). */
export const META_MAX_DEPTH = 100;

export function checkMeta(value: unknown): asserts value is Record<string, unknown> {
  if (!isObject(value)) throw new SceneError("meta", "must be an object");
  const stack: [unknown, number][] = [[value, 1]];
  while (stack.length > 0) {
    const [v, depth] = stack.pop() as [unknown, number];
    if (v === null || typeof v !== "object") continue;
    if (depth > META_MAX_DEPTH)
      throw new SceneError("meta", `must not be nested deeper than ${META_MAX_DEPTH} levels`);
    for (const child of Object.values(v)) stack.push([child, depth + 1]);
  }
}
