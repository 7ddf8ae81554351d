/**
 * What the canvas's tools produce from the pointer (or from the centre of the view, for Enter), at
 * the pointer's precision (pointerGrid.ts: the coarsest power of ten no larger than a pixel at the
 * view's scale) and checked against the frame the user saw: a disc added or moved (the moved one
 * left out of its own check), a point, a line, ray or segment, and a velocity drawn or struck
 * (rounded to what one pixel of the drag changes in it). A place the frame refuses after rounding
 * but not before is moved to the nearest round place it accepts (snapPlacement). The frame also
 * refuses a rounded place across something from the aim (sweep.ts): a disc smaller than a pixel
 * rounded to the far side of a wall or through another disc, a line rounded past a disc's centre
 * (a ray is held to the sides of its whole line: it may keep digits rather than pass a disc behind
 * it). No frame: rounded only. Pure.
 */
import type { LineKind, Vec2 } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { distanceToLine } from "./clip";
import { blockerAt, lineBlocker, type NewShape } from "./freeSpot";
import { pointerStep, roundToStep, snapPlacement } from "./pointerGrid";
import { insideQuad, segmentMeetsLine, sidesDiffer } from "./sweep";

/** Whether a line, ray or segment moved from `before` (its two ends) to `after` passes a disc's
 *  centre of `f`. */
function lineSweepsDisc(f: Frame, before: readonly Vec2[], after: readonly Vec2[], kind: LineKind): boolean {
  const [p1, p2] = before as [Vec2, Vec2];
  const [a, b] = after as [Vec2, Vec2];
  for (let i = 0; i < f.ids.length; i++) {
    const o = i * FRAME_STRIDE;
    const q: Vec2 = [f.data[o + F_X]!, f.data[o + F_Y]!];
    if (kind === "segment" ? insideQuad(q, [p1, p2, b, a]) : sidesDiffer(q, p1, p2, a, b)) return true;
  }
  return false;
}

/** Whether `shape` moved in a straight line from `aim` to `c` passes across a line of `f` or
 *  through a disc (`except` left out), or, for a segment, past a disc's centre. */
function crosses(f: Frame, shape: NewShape, aim: Vec2, c: Vec2, except: string | null): boolean {
  if (shape.kind === "segment") {
    const ends = (p: Vec2): Vec2[] => [
      [p[0] - shape.half, p[1]],
      [p[0] + shape.half, p[1]],
    ];
    return lineSweepsDisc(f, ends(aim), ends(c), "segment");
  }
  const r = shape.kind === "disc" ? shape.r : 0;
  for (const l of f.lines) if (segmentMeetsLine(aim, c, l.p1, l.p2, l.kind)) return true;
  for (let i = 0; i < f.ids.length; i++) {
    if (f.ids[i] === except) continue;
    const o = i * FRAME_STRIDE;
    const q: Vec2 = [f.data[o + F_X]!, f.data[o + F_Y]!];
    if (distanceToLine(q, aim, c, "segment") < f.data[o + F_R]! + r) return true;
  }
  return false;
}

/** Where `shape` aimed at `aim` goes (with the view at `scale` px per unit); `except`: the disc moved. */
export function placeShape(
  f: Frame | null,
  shape: NewShape,
  aim: Vec2,
  scale: number,
  except: string | null = null,
): Vec2 {
  const fits = ([c]: readonly Vec2[]) =>
    f === null ||
    (blockerAt(f, shape, c as Vec2, 0, except) === null && !crosses(f, shape, aim, c as Vec2, except));
  return snapPlacement([aim], pointerStep(scale), fits)[0] as Vec2;
}

/** Where a line, ray or segment dragged from p1 to p2 goes: its ends rounded, clear of every disc. */
export function placeLine(f: Frame | null, p1: Vec2, p2: Vec2, kind: LineKind, scale: number): [Vec2, Vec2] {
  const fits = (ends: readonly Vec2[]) =>
    f === null ||
    (lineBlocker(f, ends[0] as Vec2, ends[1] as Vec2, kind) === null &&
      !lineSweepsDisc(f, [p1, p2], ends, kind));
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

/**
 * A cue strike's velocity for a click (dx, dy) world units from the disc's centre (the strike goes
 * away from the click, `perUnit` per unit of offset), rounded as pointerVelocity rounds it; null for
 * a click at the centre itself, which gives no direction. A click so near the centre that every
 * component rounds to 0 (within about half a pixel) still strikes: the smallest velocity at that
 * precision in the strike's direction (its larger component one step, the other rounded to the same
 * step), never [0, 0], which would stop the disc: the opposite of a strike.
 */
export function strikeVelocity(dx: number, dy: number, perUnit: number, scale: number): Vec2 | null {
  if (dx === 0 && dy === 0) return null;
  const v = pointerVelocity(dx, dy, perUnit, scale);
  if (v[0] !== 0 || v[1] !== 0) return v;
  const step = pointerStep(scale / perUnit);
  const big = Math.max(Math.abs(dx), Math.abs(dy));
  return [roundToStep((dx / big) * step, step), roundToStep((dy / big) * step, step)];
}
