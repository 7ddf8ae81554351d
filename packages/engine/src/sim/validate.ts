/**
 * Input checks of the World's edits. Each check throws ChapgameError naming the field and the
 * reason, with what was given (" (got …)", refusalText.ts, as the scene's checks say it), before
 * anything is changed.
 */
import {
  FIELD_MIN,
  MAGNITUDE_MAX,
  MASS_MAX,
  MASS_MIN,
  RADIUS_MIN,
  SPEED_MIN,
  TIME_MAX,
} from "../tolerances.js";
import { ChapgameError } from "./errors.js";
import { frictionUnderGravity, given, refused, unknownField } from "./refusalText.js";
import type { Vec2 } from "./types.js";

export function requireId(path: string, id: unknown): string {
  if (typeof id !== "string" || id.length === 0) throw refused(path, "must be a non-empty string", id);
  return id;
}

export function requireFinite(path: string, v: unknown): number {
  if (typeof v !== "number" || !Number.isFinite(v)) throw refused(path, "must be a finite number", v);
  return v;
}

/**
 * A length or a rate (position, velocity, coordinate): finite, and at most MAGNITUDE_MAX in size
 * (beyond it the contact polynomials overflow; see tolerances.ts).
 */
export function requireBounded(path: string, v: unknown): number {
  const x = requireFinite(path, v);
  if (Math.abs(x) > MAGNITUDE_MAX)
    throw new ChapgameError(
      path,
      `must be at most ${MAGNITUDE_MAX} in size (got ${given(x)}): larger values overflow the contact polynomials`,
    );
  return x;
}

/**
 * A line's second point p2 given its first p1: a different point, at least RADIUS_MIN away along x
 * or y. The line's direction is p2 - p1, whose square enters every contact test: below RADIUS_MIN
 * it underflows, and a disc passed through the line or gained energy at it (review: p2 = p1 + 1e-170
 * gave no collision at all). `path` names p2 (or p1 when p2 was kept); `what` names the other end
 * ("p1", or "p2" when `path` is p1). Equal ends are refused naming the point given, e.g.
 * "must differ from p1 (got [3, 4])".
 */
export function requireLineDirection(path: string, p1: Vec2, p2: Vec2, what = "p1"): void {
  const d = Math.max(Math.abs(p2[0] - p1[0]), Math.abs(p2[1] - p1[1]));
  if (d === 0) {
    const at = what === "p1" ? p2 : p1; // the refused end, the one `path` names
    throw new ChapgameError(path, `must differ from ${what} (got [${at[0]}, ${at[1]}])`);
  }
  if (!(d >= RADIUS_MIN))
    throw new ChapgameError(
      path,
      `must be at least ${RADIUS_MIN} from ${what} in x or y (got ${d}): a shorter direction underflows the contact tests`,
    );
}

/** A velocity component given by an edit: 0, or between SPEED_MIN and MAGNITUDE_MAX in size. */
export function requireVelocity(path: string, v: unknown): number {
  const x = requireBounded(path, v);
  if (x !== 0 && Math.abs(x) < SPEED_MIN)
    throw new ChapgameError(
      path,
      `must be 0 or at least ${SPEED_MIN} in size (got ${given(x)}): smaller speeds underflow the contact polynomials`,
    );
  return x;
}

/** A radius: between RADIUS_MIN and MAGNITUDE_MAX (outside, the contact polynomials under- or overflow). */
export function requireRadius(path: string, v: unknown): number {
  const r = requirePositiveFinite(path, v);
  if (r < RADIUS_MIN || r > MAGNITUDE_MAX)
    throw new ChapgameError(
      path,
      `must be between ${RADIUS_MIN} and ${MAGNITUDE_MAX} (got ${given(r)}): the contact polynomials would under- or overflow`,
    );
  return r;
}

/** A rate that cannot be negative (g, mu): finite, >= 0 and at most MAGNITUDE_MAX. */
function requireNonNegativeBounded(path: string, v: unknown): number {
  requireNonNegativeFinite(path, v);
  return requireBounded(path, v);
}

/**
 * A friction field g or coefficient mu: 0, or between FIELD_MIN and MAGNITUDE_MAX (a smaller
 * non-zero one underflows the contact quartic; see tolerances.ts).
 */
export function requireFieldRate(path: string, v: unknown): number {
  return requireFieldMin(path, requireNonNegativeBounded(path, v));
}

/** The gravity field [gx, gy]: each component 0, or between FIELD_MIN and MAGNITUDE_MAX in size. */
export function requireGravity(path: string, v: unknown): Vec2 {
  const [gx, gy] = requireVec(path, v);
  return [requireFieldMin(`${path}[0]`, gx), requireFieldMin(`${path}[1]`, gy)];
}

function requireFieldMin(path: string, x: number): number {
  if (x !== 0 && Math.abs(x) < FIELD_MIN)
    throw new ChapgameError(
      path,
      `must be 0 or at least ${FIELD_MIN} in size (got ${given(x)}): smaller fields underflow the contact polynomials`,
    );
  return x;
}

function requirePositiveFinite(path: string, v: unknown): number {
  if (typeof v !== "number" || !Number.isFinite(v) || v <= 0)
    throw refused(path, "must be a positive finite number", v);
  return v;
}

function requireNonNegativeFinite(path: string, v: unknown): number {
  if (typeof v !== "number" || !Number.isFinite(v) || v < 0)
    throw refused(path, "must be a non-negative finite number", v);
  return v;
}

/** A mass: between MASS_MIN and MASS_MAX, or +Infinity (immovable by collisions; see tolerances.ts). */
export function requireMass(path: string, v: unknown): number {
  if (v === "Infinity")
    // a scene file's (and a motion saved as JSON's) way of writing it, passed on as it is (review
    // of session 26: the refusal said only "got the string")
    throw new ChapgameError(
      path,
      `must be a positive number (or Infinity) (got the string "Infinity"): write the number Infinity (the string is how a scene file writes it)`,
    );
  if (typeof v !== "number" || Number.isNaN(v) || v <= 0)
    throw refused(path, "must be a positive number (or Infinity)", v);
  if (v !== Number.POSITIVE_INFINITY && !(v >= MASS_MIN && v <= MASS_MAX))
    throw new ChapgameError(
      path,
      `must be between ${MASS_MIN} and ${MASS_MAX}, or Infinity (got ${given(v)}): the collision response's products would over- or underflow`,
    );
  return v;
}

/**
 * A time given to the engine (an action's time, the World's time option): finite and at most
 * TIME_MAX in size (a time multiplies velocities into positions; see tolerances.ts).
 */
export function requireTime(path: string, v: unknown): number {
  const t = requireFinite(path, v);
  if (Math.abs(t) > TIME_MAX)
    throw new ChapgameError(
      path,
      `must be at most ${TIME_MAX} in size (got ${given(t)}): later positions would leave the range of lengths (${MAGNITUDE_MAX})`,
    );
  return t;
}

/** A pair [x, y] of lengths or rates, each checked by requireBounded. */
export function requireVec(path: string, v: unknown): Vec2 {
  if (!Array.isArray(v) || v.length !== 2) throw refused(path, "must be an array of two finite numbers", v);
  return [requireBounded(`${path}[0]`, v[0]), requireBounded(`${path}[1]`, v[1])];
}

export function requireLineKind(path: string, v: unknown): "line" | "ray" | "segment" {
  if (v !== "line" && v !== "ray" && v !== "segment")
    throw refused(path, 'must be one of "line", "ray", "segment"', v); // a scene's words (scene/fields.ts)
  return v;
}

/** Friction (mu > 0 with g > 0 would be needed to matter) is refused under a non-zero gravity field. */
export function checkFrictionGravity(path: string, mu: number, gravity: Vec2): void {
  if (mu > 0 && (gravity[0] !== 0 || gravity[1] !== 0))
    throw new ChapgameError(path, frictionUnderGravity(mu));
}

/**
 * An options or fields object: a plain object (not null, not an array) whose keys are all in
 * `known` or `ignored`. `ignored` lists the keys of what the World itself reports (a BodyState's
 * id, ax, ay; a motion's ax, ay, tStop) so that such a report can be passed back as it is; they are
 * derived, so the edit does not read them. Any other key is refused by name: a misspelt field
 * (`vX`, `grav`) would otherwise be dropped without a word.
 *
 * Paths: the object itself, when it is not an object, is `path` (`init`, `patch`, `options`); a key
 * of it is `fieldsAt` + the key, where `fieldsAt` is how the checks of its known fields name them:
 * "" for an argument of a World method, whose fields are named alone (`r`, `untilTime`), so that a
 * misspelt key is named like a bad value of a known one (`radius: unknown field`, `r: must be …`),
 * as a scene file names its top-level keys (`title: unknown field`, `g: must be …`); "optimizations."
 * for the options' nested switches (`optimizations.broadphase`, `optimizations.broadPhase`).
 */
export function requireFields(
  path: string,
  v: unknown,
  known: readonly string[],
  ignored: readonly string[] = [],
  fieldsAt = "",
): void {
  if (typeof v !== "object" || v === null || Array.isArray(v))
    throw refused(path, `must be an object with fields ${known.join(", ")}`, v);
  for (const key of Object.keys(v))
    if (!known.includes(key) && !ignored.includes(key))
      throw new ChapgameError(
        `${fieldsAt}${key}`,
        // (the slip the other way round from a scene file's: actions spell a velocity v: [vx, vy])
        unknownField(known, key === "v" && known.includes("vx") ? "; a velocity is vx, vy" : ""),
      );
}

/** The fields of a BodyInit / BodyPatch, and of a BodyState that may be passed back. */
export const BODY_FIELDS = ["x", "y", "vx", "vy", "r", "m", "mu"] as const;
export const BODY_STATE_EXTRAS = ["id", "ax", "ay"] as const;
/** The fields of a BodyMotionInit, and of a motion(id) report that may be passed back. */
export const MOTION_FIELDS = ["t0", "x0", "y0", "vx", "vy", "r", "m", "mu"] as const;
export const MOTION_EXTRAS = ["id", "ax", "ay", "tStop"] as const;

/**
 * A patch's value of a body's field: the body's own current value when the patch leaves the field
 * out or gives that value back (what the World reports
 * must go back in, and gravity takes positions and speeds past the edit bounds: updateBody(id,
 * body(id)) was refused once y passed 1e30), any other value held to `check`'s bounds.
 */
export function ownOr(
  path: string,
  v: unknown,
  own: number,
  check: (path: string, v: unknown) => number,
): number {
  return v === undefined || v === own ? own : check(path, v);
}

/**
 * The place (coordinate `axis`) a motion from `t0` gives a body at the world's time `now`: refused,
 * naming t0, when it is not finite (a motion from t0 = -1e300 under gravity: it was refused as
 * `y0: must be a finite number (got -Infinity)` for a y0 of 0).
 */
export function finitePlace(axis: string, t0: number, place: number, now: number): number {
  if (Number.isFinite(place)) return place;
  throw new ChapgameError(
    "t0",
    `the motion from t0 = ${t0} puts the body at ${axis} = ${place} at the world's time ${now}, beyond the range of doubles (got ${given(t0)}): give a t0 nearer the world's time`,
  );
}
