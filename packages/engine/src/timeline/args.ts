/**
 * Checks of the Timeline methods' arguments, each naming the method and the argument:
 * - edits (prolong's until, prolongSlice's budget, setActions' list) throw a SceneError with the
 *   argument's name as its path, like the fields of an action;
 * - readings (a time, an index) throw a RangeError in the engine's form, the method and the
 *   argument as the path: `stateAt(t): must be … (got X)`, then `: why` when there is more to say
 *   (the value named as every refusal names it: sim/refusalText.ts).
 * Each returns the value to use (a time of -0 becomes 0, as in scene files).
 */
import { SceneError } from "../scene/errors.js";
import { count, isObject, nonNegative, onlyKeys, refuse } from "../scene/fields.js";
import type { Until } from "../scene/types.js";
import { given } from "../sim/refusalText.js";
import { beyondTimeMax, timeLimitReason } from "../sim/timeLimit.js";
import { TIME_MAX } from "../tolerances.js";

/** Validates apply's options: keepHorizon (default true) and checkLater (default true; false only
 *  with keepHorizon false). SceneError naming `options.<field>`. */
export function checkApplyOptions(raw: unknown): { keepHorizon: boolean; checkLater: boolean } {
  if (!isObject(raw))
    throw refuse("options", "must be an object with optional keepHorizon and checkLater", raw);
  onlyKeys(raw, ["keepHorizon", "checkLater"], "options");
  const k = raw.keepHorizon;
  if (k !== undefined && typeof k !== "boolean")
    throw refuse("options.keepHorizon", "must be true or false", k);
  const c = raw.checkLater;
  if (c !== undefined && typeof c !== "boolean")
    throw refuse("options.checkLater", "must be true or false", c);
  if (c === false && k !== false)
    throw new SceneError("options.checkLater", "can be false only with keepHorizon: false");
  return { keepHorizon: k !== false, checkLater: c !== false };
}

/** Validates an until (a prolong's argument): SceneError naming `path`'s field. */
export function checkUntil(raw: unknown, path: string): Until {
  if (!isObject(raw)) throw refuse(path, "must be an object with optional time and events", raw);
  onlyKeys(raw, ["time", "events"], path);
  const u: Until = {};
  if (raw.time !== undefined) u.time = nonNegative(raw, "time", path);
  if (raw.events !== undefined) u.events = count(raw, "events", path);
  return u;
}

/** What a prolong's refusal of a time beyond TIME_MAX suggests (sim/timeLimit.ts). */
const PROLONG_NO_LIMIT = "for no time limit leave it out, and prolong past TIME_MAX by events (until.events)";

/** A prolong's until whose time, counted from `horizon`, reaches past TIME_MAX: SceneError naming
 *  `path`.time, with the time reached (sim/timeLimit.ts). */
export function checkUntilReach(u: Until, horizon: number, path: string): void {
  if (u.time === undefined) return;
  const reached = horizon + u.time;
  if (beyondTimeMax(reached, horizon))
    throw new SceneError(
      `${path}.time`,
      timeLimitReason(u.time, reached, `the horizon ${horizon}`, PROLONG_NO_LIMIT),
    );
}

/** prolongTo's t past TIME_MAX and the horizon: SceneError naming `t` (sim/timeLimit.ts). */
export function checkProlongTo(t: number, horizon: number): void {
  if (beyondTimeMax(t, horizon)) throw new SceneError("t", timeLimitReason(t, t, "", PROLONG_NO_LIMIT));
}

/** prolongSlice's budget: a whole number >= 1, or Infinity (no budget). */
export function checkBudget(budget: unknown): number {
  if (
    typeof budget !== "number" ||
    !(budget >= 1) ||
    !(Number.isInteger(budget) || budget === Number.POSITIVE_INFINITY)
  )
    throw refuse("budget", "must be a whole number >= 1, or Infinity", budget);
  return budget;
}

/** setActions' argument: an array (its items are checked as actions[i] by the caller). */
export function checkActionList(actions: unknown): readonly unknown[] {
  if (!Array.isArray(actions)) throw refuse("actions", "must be an array of actions", actions);
  return actions;
}

/** `t` itself when it is a number (±Infinity allowed: before or after everything); else a RangeError
 *  naming the method and the argument. */
export function timeArg(method: string, name: string, t: number): number {
  if (typeof t !== "number" || Number.isNaN(t))
    throw new RangeError(`${method}(${name}): must be a number (got ${given(t)})`);
  return t;
}

/** stateAt's time (or `method`'s argument `name`): a number in [start, horizon] (-0 read as 0; start
 *  is the earliest readable time: 0, the start of the kept history after forgetBefore, the last
 *  logged entry without history); else a RangeError. `before` says why a time in [0, start) is
 *  refused (kept.ts's earliestReadable; path's `to` gives its own reason, start is its `from` then). */
export function stateTime(
  t: unknown,
  horizon: number,
  start = 0,
  method = "stateAt",
  name = "t",
  before = "",
): number {
  if (typeof t !== "number" || !(t >= start && t <= horizon)) {
    // Beyond the horizon is not computed yet, even when nothing more will happen (prolong said idle).
    // past TIME_MAX prolongTo(t) is refused (sim/timeLimit.ts): do not send the user there
    const hint =
      typeof t === "number" && t > horizon && t < Number.POSITIVE_INFINITY
        ? `: the history is computed up to ${horizon}, ${t > TIME_MAX ? `and past ${TIME_MAX} (TIME_MAX) only events take a history (prolong({ events }))` : `call prolongTo(${t}) first`}`
        : typeof t === "number" && t >= 0 && t < start && before !== ""
          ? `: ${before}`
          : "";
    throw new RangeError(
      `${method}(${name}): must be a number in [${start}, ${horizon}] (got ${given(t)})${hint}`,
    );
  }
  return t === 0 ? 0 : t;
}

/** eventRange's indices: whole numbers >= 0; the end may be Infinity (to the end of the log). */
export function indexRange(start: unknown, end: unknown): [number, number] {
  const whole = (i: unknown) => typeof i === "number" && Number.isInteger(i) && i >= 0;
  if (!whole(start)) throw new RangeError(`eventRange(start): must be an integer >= 0 (got ${given(start)})`);
  if (!(whole(end) || end === Number.POSITIVE_INFINITY))
    throw new RangeError(`eventRange(end): must be an integer >= 0 or Infinity (got ${given(end)})`);
  return [start as number, end as number];
}

/** An index into the log: a whole number in [0, count); else a RangeError naming `method`. */
export function eventIndex(method: string, i: unknown, count: number): number {
  if (!(typeof i === "number" && Number.isInteger(i) && i >= 0 && i < count))
    throw new RangeError(`${method}(index): must be an integer in [0, ${count}) (got ${given(i)})`);
  return i;
}
