/**
 * Plain-data helpers of the Timeline's action list. The actions a Timeline keeps are frozen (deep:
 * the action, its vectors, its until), so the list it hands out cannot be edited behind its back;
 * toScene hands out unfrozen copies for the caller to edit. Also: deep equality of actions, where a
 * new action list first differs from the old one (firstChange), and the keyframe setActions
 * restarts from (after the last unchanged action). Argument checks: args.ts.
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
  if (a === b) return true; // (the same frozen action: setActions given the timeline's own list)
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

/**
 * Where the action list `acts` (in applying order: by time, then as given) and its replacement
 * `sorted` first differ: the index `d` of the first action that is not the same, and its time `cut`
 * (the earlier of the two lists' actions at d; Infinity when the lists are the same).
 *
 * Actions are compared by value (sameValue), not by identity: setActions checks the list it is
 * given into fresh objects, and the lists it is given are usually copies (toScene, an undo entry,
 * a structured clone from a worker), so identity would find every action changed and recompute the
 * whole history. An action is plain data and the computation reads nothing else of it, so equal
 * values compute the same history; numbers are compared with Object.is (-0 and 0 differ), so no
 * difference the computation could see is missed. The lists are compared position by position in
 * applying order: actions at one instant apply in the order given, so swapping two of them is a
 * change at that instant, while a reordering the applying order undoes (actions at different times)
 * is none. An `until` is part of its action's value.
 */
export function firstChange(acts: readonly Action[], sorted: readonly Action[]): { d: number; cut: number } {
  let d = 0;
  while (d < sorted.length && d < acts.length && sameValue(sorted[d], acts[d])) d++;
  const cut = Math.min(
    sorted[d]?.time ?? Number.POSITIVE_INFINITY,
    acts[d]?.time ?? Number.POSITIVE_INFINITY,
  );
  return { d, cut };
}

/**
 * Whether keyframe `kf` is a point to recompute from when the first change (firstChange) is action
 * `d`, at time `cut` (`acts`: the actions, unchanged before d): taken when only unchanged actions
 * were applied, and before `cut`, or at `cut` after some of that instant's actions (the rest are
 * applied there as the same group), or at `cut` before all of them with every event there
 * processed (the instant's events come first, then its actions: restartPoint.ts).
 */
export function restartsAt(kf: Keyframe, d: number, cut: number, acts: readonly Action[]): boolean {
  if (kf.actionCount > d || kf.time > cut) return false;
  if (kf.time < cut || kf.afterActions) return true;
  return kf.atTimeLimit && (kf.actionCount === 0 || (acts[kf.actionCount - 1] as Action).time < cut);
}

/** The keyframe (holding a World) to recompute from when the first change is action `d`, at time
 *  `cut`: the last one restartsAt accepts (0 = from scratch). */
export function restartKeyframe(
  keyframes: readonly Keyframe[],
  d: number,
  cut: number,
  acts: readonly Action[],
): number {
  for (let k = keyframes.length - 1; k > 0; k--)
    if (restartsAt(keyframes[k] as Keyframe, d, cut, acts)) return k;
  return 0;
}
