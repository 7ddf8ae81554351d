/**
 * The precision of what the pointer produces. A pointer aims to about one CSS pixel, so a place it
 * gives (a click, a drag's end, the centre of the view for Enter) is rounded to the coarsest power
 * of ten no larger than one pixel in world units at the view's scale (pointerStep): at 10 px per unit
 * x = 123.45678901234 becomes 123.5, and the scene file and the tables read what the user could aim
 * at, not the digits of a division. roundToStep writes such a number as its shortest decimal
 * (Math.round(x / 0.1) * 0.1 gives 0.30000000000000004).
 * snapPlacement keeps placement honest: the rounded place is used only when the placement check
 * passes there. When it does not but the aim passes (a disc dropped less than a pixel from a wall),
 * the corners of the grid cell around the aim are tried, nearest first (a line's two ends moved
 * the same way on each axis, so a level line stays level), then those of grids ten and a hundred
 * times finer, and at worst the aim itself is used: a place a pixel off on the far side of
 * the contact is what the user aimed at, a refusal for a spot they did not choose is not, and digits
 * are a lesser harm than either. An aim that fails the check itself gets the rounded place, which the
 * engine then refuses or accepts on its own terms (rounding never turns an accepted place into a
 * refused one). Pure.
 */
import type { Vec2 } from "../engineTypes";

/** Grids finer than the pointer's tried (each ten times finer) before the aim itself is used. */
export const FINER_GRIDS = 2;

/** Past this many steps from 0 a coordinate is left as it is (its shortest decimal would need 16 digits). */
const MAX_STEPS = 1e15;

/** 10^e, exactly the double nearest to it (a decimal literal is parsed correctly rounded). */
export function tenTo(e: number): number {
  return Number(`1e${e}`);
}

/** The exponent of the largest power of ten <= x (x > 0 and finite). */
export function exponentAtMost(x: number): number {
  let e = Math.floor(Math.log10(x));
  // log10 of a number next to a power of ten may round across it
  if (tenTo(e) > x) e--;
  else if (tenTo(e + 1) <= x) e++;
  return e;
}

/** The coarsest power of ten no larger than `pixels` CSS pixels at `scale` pixels per unit. */
export function pointerStep(scale: number, pixels = 1): number {
  return tenTo(exponentAtMost(pixels / scale));
}

type Rounding = (x: number) => number;

/**
 * x rounded to a multiple of `step` (a power of ten, as pointerStep gives) by `mode` (nearest by
 * default), written as its shortest decimal; x itself when it is not finite or so far from 0 that
 * no shorter decimal exists.
 */
export function roundToStep(x: number, step: number, mode: Rounding = Math.round): number {
  if (!Number.isFinite(x) || Math.abs(x) / step >= MAX_STEPS) return x;
  const e = Math.round(Math.log10(step));
  // one rounding each way: n * 10^d is the scaled value, n / 10^d the double nearest the decimal
  const n = e < 0 ? mode(x * tenTo(-e)) : mode(x / tenTo(e));
  if (n === 0) return 0; // never -0
  return e < 0 ? n / tenTo(-e) : n * tenTo(e);
}

/** A point rounded to `step` on both axes. */
export function roundPoint(p: Vec2, step: number): Vec2 {
  return [roundToStep(p[0], step), roundToStep(p[1], step)];
}

const distance = (a: Vec2, b: Vec2): number => Math.hypot(a[0] - b[0], a[1] - b[1]);

/** Down or up on each axis. */
const MODES: [Rounding, Rounding][] = [
  [Math.floor, Math.floor],
  [Math.floor, Math.ceil],
  [Math.ceil, Math.floor],
  [Math.ceil, Math.ceil],
];

/**
 * The aimed points moved to a corner of their cell of the grid of `step`, all the same way on each
 * axis (a line drawn level stays level), the choice that strays least from the aim first.
 */
function cornerChoices(aim: readonly Vec2[], step: number): Vec2[][] {
  const choices = MODES.map(([mx, my]) =>
    aim.map((p): Vec2 => [roundToStep(p[0], step, mx), roundToStep(p[1], step, my)]),
  );
  const stray = (c: Vec2[]) => Math.max(...c.map((q, i) => distance(q, aim[i] as Vec2)));
  return choices.sort((a, b) => stray(a) - stray(b));
}

/**
 * Where to put what the pointer aimed at `aim` (one point, or a line's two ends), on the grid of
 * `step` when `fits` accepts it there (see the module comment for the order tried). `fits` is the
 * placement check of the frame the user saw.
 */
export function snapPlacement(
  aim: readonly Vec2[],
  step: number,
  fits: (points: readonly Vec2[]) => boolean,
): Vec2[] {
  const rounded = aim.map((p) => roundPoint(p, step));
  if (fits(rounded) || !fits(aim)) return rounded;
  const e = Math.round(Math.log10(step));
  for (let finer = 0; finer <= FINER_GRIDS; finer++)
    for (const choice of cornerChoices(aim, tenTo(e - finer))) if (fits(choice)) return choice;
  return aim.map((p) => [p[0], p[1]]);
}
