/**
 * Helpers of the parseScene tests (parse*.test.ts): a scene's JSON text around some actions, a disc's
 * addBody action, and the SceneError parseScene throws for an input it must refuse.
 */
import { expect } from "vitest";
import { SceneError } from "./errors.js";
import { parseScene } from "./parse.js";

/** A scene file's JSON text with these actions (format and version 1) and any other top-level fields. */
export const base = (actions: unknown[], extra: Record<string, unknown> = {}) =>
  JSON.stringify({ format: "chapgame", version: 1, actions, ...extra });

/** An addBody at time 0 of a unit disc at (x, 0), with any fields overridden by `more`. */
export const disc = (id: string, x: number, more: Record<string, unknown> = {}) => ({
  time: 0,
  type: "addBody",
  id,
  x,
  y: 0,
  r: 1,
  m: 1,
  ...more,
});

/** The SceneError parseScene throws for `input` (fails the test when it accepts it or throws another error). */
export function refused(input: unknown): SceneError {
  try {
    parseScene(input);
  } catch (e) {
    expect(e).toBeInstanceOf(SceneError);
    return e as SceneError;
  }
  throw new Error("parseScene accepted invalid input");
}
