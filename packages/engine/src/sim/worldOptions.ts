/**
 * The checks of `new World(options)` (WorldOptions): only the known keys, each optimisation switch
 * true or false, then g, gravity and time, in this order; the first bad one throws ChapgameError
 * naming it (`gx`, `optimizations.broadphase`, `optimizations.broadPhase`, `g`, `gravity[0]`, `time`). Returns the
 * values to build the World with, the defaults filled in.
 */
import { refused } from "./refusalText.js";
import type { Optimizations, Vec2, WorldOptions } from "./types.js";
import { requireFieldRate, requireFields, requireGravity, requireTime } from "./validate.js";

/** The switches of WorldOptions.optimizations. */
const OPTIMIZATION_KEYS = [
  "broadPhase",
  "pathBounds",
  "quadraticFastPath",
  "restingSkip",
  "recedingReject",
] as const;

/** `options` checked, with g (default 9.81), gravity ([0, 0]), time (0) and optimizations ({}). */
export function checkWorldOptions(options: WorldOptions): {
  g: number;
  gravity: Vec2;
  time: number;
  optimizations: Optimizations;
} {
  requireFields("options", options, ["g", "gravity", "time", "optimizations"]);
  if (options.optimizations !== undefined) {
    requireFields("optimizations", options.optimizations, OPTIMIZATION_KEYS, [], "optimizations.");
    // Each switch a boolean: "no" or 3 would be taken as on.
    for (const key of OPTIMIZATION_KEYS) {
      const v = options.optimizations[key];
      if (v !== undefined && typeof v !== "boolean")
        throw refused(`optimizations.${key}`, "must be true or false", v);
    }
  }
  const g = requireFieldRate("g", options.g ?? 9.81);
  const gravity = requireGravity("gravity", options.gravity ?? [0, 0]);
  const time = requireTime("time", options.time ?? 0);
  return { g, gravity, time, optimizations: options.optimizations ?? {} };
}
