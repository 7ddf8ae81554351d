/**
 * Reading one body of a World out of its BodyStore: its exact state at a time (World.body, bodies)
 * and its current motion (World.motion). A state is the closed-form motion evaluated with
 * physics/motion.ts: x = positionAt(t0, x0, vx0, ax, min(t, tEnd)), the same for y; velocity and
 * acceleration while t < tEnd, 0 after (a friction stop). bodyArrays.ts writes the same numbers
 * into arrays. A time before the motion's start is refused (requireStarted): a World keeps no past.
 */
import { positionAt, velocityAt } from "../physics/motion.js";
import type { BodyStore } from "./bodyStore.js";
import { ChapgameError } from "./errors.js";
import { given, quoteId } from "./refusalText.js";
import type { BodyMotion, BodyState } from "./types.js";

/** Throws ChapgameError naming `t` when t is before slot s's current motion started (or NaN). */
export function requireStarted(b: BodyStore, s: number, t: number): void {
  if (!(t >= (b.mot[s * 8 + 0] as number)))
    throw new ChapgameError(
      "t",
      `must be a time at or after body ${quoteId(b.ids[s] as string)}'s last event or edit, t0 = ${b.mot[s * 8 + 0]} (got ${given(t)}): earlier states are not kept by a World (a Timeline keeps them)`,
    );
}

/** The state of slot s at time t (requireStarted first). */
export function stateOf(b: BodyStore, s: number, t: number): BodyState {
  requireStarted(b, s, t);
  const tEnd = b.mot[s * 8 + 7] as number;
  const te = Math.min(t, tEnd);
  const t0 = b.mot[s * 8 + 0] as number;
  const ax = b.mot[s * 8 + 5] as number;
  const ay = b.mot[s * 8 + 6] as number;
  const moving = t < tEnd;
  return {
    id: b.ids[s] as string,
    x: positionAt(t0, b.mot[s * 8 + 1] as number, b.mot[s * 8 + 3] as number, ax, te),
    y: positionAt(t0, b.mot[s * 8 + 2] as number, b.mot[s * 8 + 4] as number, ay, te),
    vx: moving ? velocityAt(t0, b.mot[s * 8 + 3] as number, ax, t) : 0,
    vy: moving ? velocityAt(t0, b.mot[s * 8 + 4] as number, ay, t) : 0,
    ax: moving ? ax : 0,
    ay: moving ? ay : 0,
    r: b.r[s] as number,
    m: b.m[s] as number,
    mu: b.mu[s] as number,
  };
}

/** The current motion of slot s (a copy). */
export function motionOf(b: BodyStore, s: number): BodyMotion {
  return {
    t0: b.mot[s * 8 + 0] as number,
    x0: b.mot[s * 8 + 1] as number,
    y0: b.mot[s * 8 + 2] as number,
    vx: b.mot[s * 8 + 3] as number,
    vy: b.mot[s * 8 + 4] as number,
    ax: b.mot[s * 8 + 5] as number,
    ay: b.mot[s * 8 + 6] as number,
    tStop: b.mot[s * 8 + 7] as number,
  };
}
