/**
 * Input checks of the World's edits. Each check throws ChapgameError naming the field and the
 * reason, before anything is changed.
 */
import { ChapgameError } from "./errors.js";
import type { Vec2 } from "./types.js";

export function requireId(path: string, id: unknown): string {
  if (typeof id !== "string" || id.length === 0) throw new ChapgameError(path, "must be a non-empty string");
  return id;
}

export function requireFinite(path: string, v: unknown): number {
  if (typeof v !== "number" || !Number.isFinite(v)) throw new ChapgameError(path, "must be a finite number");
  return v;
}

export function requirePositiveFinite(path: string, v: unknown): number {
  if (typeof v !== "number" || !Number.isFinite(v) || v <= 0)
    throw new ChapgameError(path, "must be a positive finite number");
  return v;
}

export function requireNonNegativeFinite(path: string, v: unknown): number {
  if (typeof v !== "number" || !Number.isFinite(v) || v < 0)
    throw new ChapgameError(path, "must be a finite number >= 0");
  return v;
}

/** A mass: positive, finite or +Infinity (immovable by collisions). */
export function requireMass(path: string, v: unknown): number {
  if (typeof v !== "number" || Number.isNaN(v) || v <= 0)
    throw new ChapgameError(path, "must be a positive number (or Infinity)");
  return v;
}

export function requireVec(path: string, v: unknown): Vec2 {
  if (!Array.isArray(v) || v.length !== 2)
    throw new ChapgameError(path, "must be a pair of finite numbers [x, y]");
  return [requireFinite(`${path}[0]`, v[0]), requireFinite(`${path}[1]`, v[1])];
}

export function requireLineKind(path: string, v: unknown): "line" | "ray" | "segment" {
  if (v !== "line" && v !== "ray" && v !== "segment")
    throw new ChapgameError(path, `must be "line", "ray" or "segment" (got ${JSON.stringify(v)})`);
  return v;
}

/** Friction (mu > 0 with g > 0 would be needed to matter) is refused under a non-zero gravity field. */
export function checkFrictionGravity(path: string, mu: number, gravity: Vec2): void {
  if (mu > 0 && (gravity[0] !== 0 || gravity[1] !== 0))
    throw new ChapgameError(
      path,
      "must be 0 while the gravity field is non-zero (friction under gravity is not polynomial motion)",
    );
}
