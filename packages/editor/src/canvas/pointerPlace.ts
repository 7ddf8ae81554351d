/**
 * What the canvas's tools produce from the pointer (or from the centre of the view, for Enter), at
 * the pointer's precision (pointerGrid.ts: the coarsest power of ten no larger than a pixel at the
 * view's scale) and checked against the frame the user saw: a disc added or moved (the moved one
 * left out of its own check), a point, a line, ray or segment, and a velocity drawn or struck
 * (rounded to what one pixel of the drag changes in it). A place the frame refuses after rounding
 * but not before is moved to the nearest round place it accepts (snapPlacement). No frame: rounded
 * only. Pure.
 */
import type { LineKind, Vec2 } from "../engineTypes";
import type { Frame } from "../remote/protocol";
import { blockerAt, lineBlocker, type NewShape } from "./freeSpot";
import { pointerStep, roundToStep, snapPlacement } from "./pointerGrid";

/** Where `shape` aimed at `aim` goes (with the view at `scale` px per unit); `except`: the disc moved. */
export function placeShape(
  f: Frame | null,
  shape: NewShape,
  aim: Vec2,
  scale: number,
  except: string | null = null,
): Vec2 {
  const fits = ([c]: readonly Vec2[]) => f === null || blockerAt(f, shape, c as Vec2, 0, except) === null;
  return snapPlacement([aim], pointerStep(scale), fits)[0] as Vec2;
}

/** Where a line, ray or segment dragged from p1 to p2 goes: its ends rounded, clear of every disc. */
export function placeLine(f: Frame | null, p1: Vec2, p2: Vec2, kind: LineKind, scale: number): [Vec2, Vec2] {
  const fits = ([a, b]: readonly Vec2[]) => f === null || lineBlocker(f, a as Vec2, b as Vec2, kind) === null;
  const [a, b] = snapPlacement([p1, p2], pointerStep(scale), fits);
  return [a as Vec2, b as Vec2];
}

/**
 * A velocity given by a drag of (dx, dy) world units, `perUnit` per unit of drag (1 / the arrow's
 * seconds, or the cue's strike rate): each component rounded to the coarsest power of ten no larger
 * than what one pixel of drag changes in it.
 */
export function pointerVelocity(dx: number, dy: number, perUnit: number, scale: number): Vec2 {
  const step = pointerStep(scale / perUnit);
  return [roundToStep(dx * perUnit, step), roundToStep(dy * perUnit, step)];
}
