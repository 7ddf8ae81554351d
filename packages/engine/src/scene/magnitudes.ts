/**
 * The World's magnitude limits (tolerances.ts: MAGNITUDE_MAX, RADIUS_MIN, SPEED_MIN, FIELD_MIN,
 * MASS_MIN, MASS_MAX, TIME_MAX for an action's time) applied to scene fields, so that a scene parseScene accepts is not refused by the Timeline later
 * for a size, and the refusal names the scene's field (`actions[2].v[0]`, not the World's `vx`).
 * The checks are sim/validate.ts's own, so scene and World agree on every bound.
 * checkActionMagnitudes(action, path) and checkFieldMagnitudes(g, gravity, path) throw SceneError.
 */
import { ChapgameError } from "../sim/errors.js";
import {
  requireBounded,
  requireFieldRate,
  requireGravity,
  requireLineDirection,
  requireMass,
  requireRadius,
  requireTime,
  requireVec,
  requireVelocity,
} from "../sim/validate.js";
import { SceneError } from "./errors.js";
import { join } from "./fields.js";
import type { Action, Vec2 } from "./types.js";

/** Runs a World check; its ChapgameError becomes a SceneError under `path`. */
function under(path: string, check: () => unknown): void {
  try {
    check();
  } catch (e) {
    if (e instanceof ChapgameError && !(e instanceof SceneError))
      throw new SceneError(join(path, e.path), e.reason);
    throw e;
  }
}

function velocity(path: string, v: Vec2 | undefined): void {
  if (v === undefined) return;
  under(path, () => requireVelocity("v[0]", v[0]));
  under(path, () => requireVelocity("v[1]", v[1]));
}

/** The friction field g and the gravity field of a scene, a setGlobal or the Timeline's options. */
export function checkFieldMagnitudes(g: number | undefined, gravity: Vec2 | undefined, path: string): void {
  if (g !== undefined) under(path, () => requireFieldRate("g", g));
  if (gravity !== undefined) under(path, () => requireGravity("gravity", gravity));
}

/** One field-checked action (checkAction's output). */
export function checkActionMagnitudes(a: Action, path: string): void {
  under(path, () => requireTime("time", a.time));
  switch (a.type) {
    case "addBody":
    case "updateBody":
      if (a.x !== undefined) under(path, () => requireBounded("x", a.x));
      if (a.y !== undefined) under(path, () => requireBounded("y", a.y));
      if (a.r !== undefined) under(path, () => requireRadius("r", a.r));
      if (a.m !== undefined) under(path, () => requireMass("m", a.m));
      if (a.mu !== undefined) under(path, () => requireFieldRate("mu", a.mu));
      velocity(path, a.v);
      return;
    case "giveVelocity":
      velocity(path, a.v);
      return;
    case "addLine":
    case "updateLine":
      if (a.p1 !== undefined) under(path, () => requireVec("p1", a.p1));
      if (a.p2 !== undefined) under(path, () => requireVec("p2", a.p2));
      return;
    case "addPoint":
    case "updatePoint":
      under(path, () => requireVec("p", a.p));
      return;
    case "setGlobal":
      checkFieldMagnitudes(a.g, a.gravity, path);
      return;
    default:
      return;
  }
}

/** sim/validate.ts requireLineDirection for a scene's line, as a SceneError at `path` (p1 and p2 as
 *  the line will have them; `what` names the other point in the message). */
export function lineDirection(path: string, p1: Vec2, p2: Vec2, what: string): void {
  try {
    requireLineDirection(path, p1, p2, what);
  } catch (e) {
    if (e instanceof ChapgameError && !(e instanceof SceneError)) throw new SceneError(path, e.reason);
    throw e;
  }
}
