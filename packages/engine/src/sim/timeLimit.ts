/**
 * The bound on the times a computation is asked to reach (TIME_MAX, tolerances.ts, says why): the
 * World's `advance({ untilTime })` and the time of a World read (`body`, `bodies`, `bodyArrays`),
 * the Timeline's `prolongTo(t)`, its horizon plus a prolong's `until.time`, an action's time plus
 * its `until.time`, and the command line's times. A finite time beyond TIME_MAX that lies ahead of
 * where the clock already is gets refused, naming the field, the value given and the time it would
 * reach; Infinity (no time limit) stays allowed where it was. The clock still passes TIME_MAX by
 * events (a run bounded by events, or not at all), at the events' own times. Checked once per call,
 * never per event; a limit within the bound costs one comparison.
 */
import { TIME_MAX } from "../tolerances.js";
import { ChapgameError } from "./errors.js";
import { given } from "./refusalText.js";

/** One rounding of a time at TIME_MAX (ulp(1e30) = 2^47, about 1.4e14). */
const ULP_AT_TIME_MAX = 2 ** 47;

/** Why, and what to do instead: the tail of every refusal of a time beyond TIME_MAX. */
export const BEYOND_TIME_MAX_WHY =
  `past it one rounding of the time (${ULP_AT_TIME_MAX} at ${TIME_MAX}) is larger than most discs, ` +
  "and a motion under gravity leaves the range of doubles (gravity 1e30 puts a body at y = -Infinity at t = 1e200)";

/** True when a computation asked to reach `reached`, from a clock at `now`, goes past TIME_MAX. */
export function beyondTimeMax(reached: number, now: number): boolean {
  return reached > TIME_MAX && reached > now && reached !== Number.POSITIVE_INFINITY;
}

/**
 * The reason a time limit is refused for: `value` was given, `reached` is the absolute time it asks
 * for (the same number, or a start plus a duration, `from` naming that start), `noLimit` how to ask
 * for no time limit.
 */
export function timeLimitReason(value: number, reached: number, from: string, noLimit: string): string {
  const got = from === "" ? given(value) : `${given(value)}, reaching t = ${reached} from ${from}`;
  return `must reach at most ${TIME_MAX} (TIME_MAX) (got ${got}): ${BEYOND_TIME_MAX_WHY}; ${noLimit}`;
}

/** The World's untilTime, or a read's time t: ChapgameError naming `path` when beyond TIME_MAX. */
export function requireWorldLimit(path: string, t: number, now: number, noLimit: string): void {
  if (beyondTimeMax(t, now)) throw new ChapgameError(path, timeLimitReason(t, t, "", noLimit));
}
