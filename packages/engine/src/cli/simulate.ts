/**
 * `simulate`: how far it computes and why it stopped. Without --until-time and --max-events, a scene
 * whose actions carry an `until` is computed as far as they say (sceneBound: every action applied
 * and each until met, what Timeline.fromScene computes), with "reason": "until" (or "idle");
 * options given on the command line win over the scene's. simulate(tl, cmd, bound, line)
 * computes in slices (a generator: an interrupt is thrown in at a yield) and returns the time to
 * print the bodies at and the reason.
 */
import type { SceneFile, Until } from "../scene/types.js";
import type { Timeline } from "../timeline/timeline.js";
import type { ProlongResult } from "../timeline/types.js";
import type { Command } from "./args.js";
import type { ProgressLine } from "./progress.js";

/**
 * The scene's own bound, when one of its actions has an `until`: up to its last action's time,
 * counted from horizon 0 (a Timeline made with the untils option goes on until every until is met).
 * Null when no action has one.
 */
export function sceneBound(scene: SceneFile): Until | null {
  let last = 0;
  let any = false;
  for (const a of scene.actions) {
    if (a.time > last) last = a.time;
    if (a.until !== undefined) any = true;
  }
  return any ? { time: last } : null;
}

/** Why a simulate run stopped (without an error or an interrupt) and the time to print the bodies at. */
export type SimulateEnd = { time: number; reason: ProlongResult["reason"] | "until" };

/**
 * Runs `simulate`; returns the time to print the bodies at and why the run stopped: "idle" when
 * no event or action is left at all (checked exactly), else "time" or "events", or "until" when the
 * scene's own bound (`bound`: its actions' untils) stopped it. With --until-time T the time is T
 * unless an event limit stopped the run earlier with more to come: a scene with nothing left before
 * T still moves (discs gliding for ever), and its state at T is exact. With the scene's bound the
 * time is where it ended (the bodies may glide on). Otherwise an idle run stops at its last event or
 * action.
 */
export function* simulate(
  tl: Timeline,
  cmd: Extract<Command, { command: "simulate" }>,
  bound: Until | null,
  line: ProgressLine,
): Generator<void, SimulateEnd, void> {
  if (bound !== null) {
    // the bound is the last action; the untils may take the run further: no time goal to show
    yield* line.compute(tl, bound, {});
    return { time: tl.horizon, reason: tl.nothingLeft() ? "idle" : "until" };
  }
  const until: Until = {};
  if (cmd.untilTime !== undefined) until.time = cmd.untilTime;
  if (cmd.maxEvents !== undefined) until.events = cmd.maxEvents;
  const reason = yield* line.compute(tl, until);
  // "idle" exactly: the World's own reason can be "time" while only cell crossings are queued (a
  // glide with no event left), and an event limit can land on the last event.
  if (reason !== "idle" && !tl.nothingLeft()) return { time: tl.horizon, reason };
  const time = cmd.untilTime ?? tl.lastLoggedTime();
  if (tl.horizon < time) tl.prolong({ time }); // nothing happens on the way: the state at T is exact
  return { time, reason: "idle" };
}
