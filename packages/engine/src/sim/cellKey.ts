/**
 * The key of a cell (cx, cy) of a spatial hash (scene/discGrid.ts, sim/obstacleCells.ts): a Map key
 * that is a small integer near the origin, a number farther out and a string beyond, the three
 * kinds never meeting, so that any pair of whole numbers has its own key.
 */

/** Cell numbers below this in size make a small integer key, -1 - ((cx + SMALL) * 2 SMALL + (cy +
 *  SMALL)), in [-2^30, -1] (a small integer for V8, whatever the build); below OFFSET a numeric key
 *  (cx + OFFSET) * SPAN + (cy + OFFSET), exact in a double (both factors < 2^26) and > 0; beyond it
 *  the key is a string. */
const SMALL = 2 ** 14;
const OFFSET = 2 ** 25;
const SPAN = 2 ** 26;

/** The key of cell (cx, cy) (whole numbers). */
export function cellKey(cx: number, cy: number): number | string {
  if (cx > -SMALL && cx < SMALL && cy > -SMALL && cy < SMALL)
    return -1 - ((cx + SMALL) * 2 * SMALL + (cy + SMALL));
  return cx > -OFFSET && cx < OFFSET && cy > -OFFSET && cy < OFFSET
    ? (cx + OFFSET) * SPAN + (cy + OFFSET)
    : `${cx}:${cy}`;
}
