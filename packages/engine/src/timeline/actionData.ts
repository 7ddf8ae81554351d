/**
 * Plain-data helpers of the Timeline's action list. The actions a Timeline keeps are frozen (deep:
 * the action, its vectors, its until), so the list it hands out cannot be edited behind its back;
 * toScene hands out unfrozen copies for the caller to edit. Also: deep equality of actions, the
 * keyframe setActions restarts from (after the last unchanged action). Argument checks: args.ts.
 */
import type { Action, Until } from "../scene/types.js";
import type { Keyframe } from "./keyframe.js";

/** `a` (a fresh object from checkAction) frozen with its arrays and its until; returns it. */
export function freezeAction(a: Action): Action {
  for (const v of Object.values(a)) if (typeof v === "object" && v !== null) Object.freeze(v);
  return Object.freeze(a);
}

/** A deep, unfrozen copy of an action (its values are numbers, strings, vectors and an until). */
export function copyAction(a: Action): Action {
  const out: Record<string, unknown> = {};
  for (const [k, v] of Object.entries(a))
    out[k] = Array.isArray(v) ? [...v] : typeof v === "object" && v !== null ? { ...v } : v;
  return out as unknown as Action;
}

/** Deep equality of plain data (numbers by Object.is, so -0 and 0 differ). */
export function sameValue(a: unknown, b: unknown): boolean {
  if (typeof a === "number" || typeof b === "number") return Object.is(a, b);
  if (typeof a !== "object" || typeof b !== "object" || a === null || b === null) return a === b;
  const ka = Object.keys(a);
  const kb = Object.keys(b);
  if (ka.length !== kb.length) return false;
  const ra = a as Record<string, unknown>;
  const rb = b as Record<string, unknown>;
  return ka.every((key) => Object.hasOwn(rb, key) && sameValue(ra[key], rb[key]));
}

export function sameUntil(a: Until, b: Until): boolean {
  return a.time === b.time && a.events === b.events;
}

/** The keyframe (holding a World) to recompute from when the action list `acts` becomes `sorted`:
 *  the last one before the first changed action, taken when only unchanged actions were applied
 *  (0 = from scratch). */
export function restartKeyframe(
  acts: readonly Action[],
  keyframes: readonly Keyframe[],
  sorted: readonly Action[],
): number {
  let d = 0;
  while (d < sorted.length && d < acts.length && sameValue(sorted[d], acts[d])) d++;
  const cut = Math.min(
    sorted[d]?.time ?? Number.POSITIVE_INFINITY,
    acts[d]?.time ?? Number.POSITIVE_INFINITY,
  );
  for (let k = keyframes.length - 1; k > 0; k--) {
    const kf = keyframes[k] as Keyframe;
    if (kf.actionCount <= d && kf.time < cut) return k;
  }
  return 0;
}
