/**
 * The closing pocket: a proof that a disc is shut in by a chain of still sides and a moving
 * immovable disc that closes in on it, so that the exact model has infinitely many events before a
 * time t* (used by the trap watch, trapWatch.ts). Pure functions; geometry in pocketGeometry.ts.
 *
 * The disc (centre c, radius r) keeps its centre out of closed convex sets: the cores S1 .. Sm of
 * the still sides (lines, points, immovable discs at rest; m = 2 or 3) widened by their own radius
 * + r', and P's disc (an immovable disc of radius R, moving by its motion law) widened to R + r'.
 * r' = r (1 - ZENO_TRAP_SLACK) is a little less than r, so that round-off overlaps of a few ulps
 * leave c outside the sets; every test below is made with a further margin of the same size, so
 * that its own round-off cannot turn it. The proof:
 *
 * 1. Each z_i lies in S_i and S_i+1 (a crossing of their borders, or the point of one nearest to P).
 * 2. q1 and qm, the points of S1 and Sm nearest to P's centre, lie in P's disc too.
 * 3. The polygon q1 z_1 .. z_m-1 qm winds around c: a closed curve whose edges lie in S1, S2, ..,
 *    Sm and P's disc (each set convex), in the union of the sets, which c stays out of.
 * 4. At t*, no later than P's motion law ends, every z_i lies in P's disc (each time found by
 *    Newton's method, the latest taken, then all checked there).
 * 5. Over [now, t*] P's disc still meets S1 and Sm: checked at the control points of the path's
 *    quadratic Bézier, whose triangle holds the path (a distance to a convex set is convex). The
 *    polygon (its ends the points of S1 and Sm nearest to P) then moves continuously, never over c,
 *    and keeps winding around it.
 * 6. (The caller's part.) Nothing changes P's motion before t*: its path meets no obstacle or other
 *    immovable disc, and no other immovable disc moves.
 *
 * At t* every vertex of the polygon lies in P's disc, which is convex: so does the polygon, which
 * then cannot wind around c, outside that disc. A disc that moves continuously, with finitely many
 * collisions, cannot get there: infinitely many events happen before t*.
 *
 * The report waits until P is within ZENO_TRAP_GAP × r of closing the pocket (see there).
 */
import { positionAt, velocityAt } from "../physics/motion.js";
import { ZENO_TRAP_GAP, ZENO_TRAP_SCALE, ZENO_TRAP_SLACK } from "../tolerances.js";
import {
  borderCrossings,
  type Core,
  coreDistance,
  coreNearest,
  length,
  windingNumber,
} from "./pocketGeometry.js";

const near = new Float64Array(2);

/** The point of the core widened by rad + reach nearest to (x, y) (the point itself when inside). */
function widenedNearest(core: Core, reach: number, x: number, y: number, out: Float64Array): void {
  coreNearest(core, x, y, near);
  const nx = near[0] as number;
  const ny = near[1] as number;
  const d = length(x - nx, y - ny);
  const L = core.rad + reach;
  if (d <= L) {
    out[0] = x;
    out[1] = y;
    return;
  }
  out[0] = nx + ((x - nx) * L) / d;
  out[1] = ny + ((y - ny) * L) / d;
}

/** Largest magnitude among a core's numbers. */
function coreSize(k: Core): number {
  return Math.max(Math.abs(k.x1), Math.abs(k.y1), Math.abs(k.x2), Math.abs(k.y2), k.rad);
}

/**
 * A time by which P's centre comes within `accept` of z, found by Newton's method on
 * |p(t) - z|² = target² from `now` (target < accept: the iterates cross accept before the root),
 * or NaN when P does not approach z, or not before `tEnd`.
 */
export function closingTime(
  now: number,
  mot: ArrayLike<number>,
  at: number,
  zx: number,
  zy: number,
  target: number,
  accept: number,
): number {
  const t0 = mot[at] as number;
  const tEnd = mot[at + 7] as number;
  let t = now;
  for (let i = 0; i < 100; i++) {
    const dx = positionAt(t0, mot[at + 1] as number, mot[at + 3] as number, mot[at + 5] as number, t) - zx;
    const dy = positionAt(t0, mot[at + 2] as number, mot[at + 4] as number, mot[at + 6] as number, t) - zy;
    if (length(dx, dy) <= accept) return t;
    const slope =
      2 *
      (dx * velocityAt(t0, mot[at + 3] as number, mot[at + 5] as number, t) +
        dy * velocityAt(t0, mot[at + 4] as number, mot[at + 6] as number, t));
    if (!(slope < 0)) return Number.NaN;
    const next = t - (dx * dx + dy * dy - target * target) / slope;
    if (!(next > t) || next > tEnd) return Number.NaN;
    t = next;
  }
  return Number.NaN;
}

const q = new Float64Array(2);

/**
 * The time t* by which the disc (centre (cx, cy), radius r) is crushed in the pocket of the chain
 * of cores `sides` (2 or 3, each meeting the next) and the immovable disc of radius R whose motion
 * is mot[at .. at + 7] (t0, x0, y0, vx, vy, ax, ay, tEnd), proven at `now` by steps 1-5 above
 * while P is within ZENO_TRAP_GAP × r of closing it; NaN when there is no such proof. `hull`
 * receives the triangle holding P's path over [now, t*] (x0, y0, x1, y1, x2, y2), for the caller's
 * step 6. `moreSize`: the magnitude of further numbers the disc's position carries the round-off
 * of (its time × speed).
 */
export function pocketCloses(
  now: number,
  cx: number,
  cy: number,
  r: number,
  mot: ArrayLike<number>,
  at: number,
  R: number,
  sides: readonly Core[],
  hull: Float64Array,
  moreSize: number,
): number {
  const t0 = mot[at] as number;
  const px = positionAt(t0, mot[at + 1] as number, mot[at + 3] as number, mot[at + 5] as number, now);
  const py = positionAt(t0, mot[at + 2] as number, mot[at + 4] as number, mot[at + 6] as number, now);
  const vx = velocityAt(t0, mot[at + 3] as number, mot[at + 5] as number, now);
  const vy = velocityAt(t0, mot[at + 4] as number, mot[at + 6] as number, now);
  let size = Math.max(
    Math.abs(cx),
    Math.abs(cy),
    Math.abs(px),
    Math.abs(py),
    R,
    Math.abs(now) * length(vx, vy),
    moreSize,
  );
  for (const k of sides) size = Math.max(size, coreSize(k));
  // Round-off must stay far below the margins, which are ZENO_TRAP_SLACK × r.
  if (!(size <= ZENO_TRAP_SCALE * r)) return Number.NaN;
  const verify = r * (1 - 1.5 * ZENO_TRAP_SLACK);
  const build = r * (1 - 2 * ZENO_TRAP_SLACK);
  const aim = r * (1 - 3 * ZENO_TRAP_SLACK);
  const first = sides[0] as Core;
  const last = sides[sides.length - 1] as Core;
  const reaches = (x: number, y: number, k: Core): boolean => coreDistance(k, x, y) <= R + k.rad + 2 * verify;
  if (!reaches(px, py, first) || !reaches(px, py, last)) return Number.NaN;
  // Step 2 (q1, qm built a margin inside their sets; the segment from each to the point of the
  // proof's set nearest to P lies in both, so the polygon below winds as the proof's curve).
  const polygon: number[] = [];
  for (const k of [first, last]) {
    widenedNearest(k, build, px, py, q);
    const qx = q[0] as number;
    const qy = q[1] as number;
    if (!(length(qx - px, qy - py) <= R + verify)) return Number.NaN;
    polygon.push(qx, qy);
  }
  // Step 1: z_i, the candidate verified in both sets that is nearest to P.
  const zs: number[] = [];
  for (let i = 0; i + 1 < sides.length; i++) {
    const z = meeting(sides[i] as Core, sides[i + 1] as Core, build, verify, px, py);
    if (z === null) return Number.NaN;
    zs.push(z[0], z[1]);
  }
  // Not yet within ZENO_TRAP_GAP r of closing; or closed already (only round-off could then have
  // put c inside: no proof).
  let farthest = 0;
  for (let i = 0; i < zs.length; i += 2)
    farthest = Math.max(farthest, length(px - (zs[i] as number), py - (zs[i + 1] as number)));
  if (farthest - (R + verify) > ZENO_TRAP_GAP * r || farthest <= R + verify) return Number.NaN;
  // Step 3: the polygon q1, z_1 .. z_m-1, qm.
  const ring = [
    polygon[0] as number,
    polygon[1] as number,
    ...zs,
    polygon[2] as number,
    polygon[3] as number,
  ];
  if (windingNumber(ring, cx, cy) === 0) return Number.NaN;
  // Step 4.
  let tStar = now;
  for (let i = 0; i < zs.length; i += 2) {
    const t = closingTime(now, mot, at, zs[i] as number, zs[i + 1] as number, R + aim, R + verify);
    if (Number.isNaN(t)) return Number.NaN;
    tStar = Math.max(tStar, t);
  }
  const ex = positionAt(t0, mot[at + 1] as number, mot[at + 3] as number, mot[at + 5] as number, tStar);
  const ey = positionAt(t0, mot[at + 2] as number, mot[at + 4] as number, mot[at + 6] as number, tStar);
  for (let i = 0; i < zs.length; i += 2)
    if (!(length(ex - (zs[i] as number), ey - (zs[i + 1] as number)) <= R + verify)) return Number.NaN;
  // Step 5: the Bézier control points of P's path over [now, t*].
  const half = 0.5 * (tStar - now);
  hull[0] = px;
  hull[1] = py;
  hull[2] = px + vx * half;
  hull[3] = py + vy * half;
  hull[4] = ex;
  hull[5] = ey;
  for (let k = 2; k < 6; k += 2) {
    const x = hull[k] as number;
    const y = hull[k + 1] as number;
    if (!reaches(x, y, first) || !reaches(x, y, last)) return Number.NaN;
  }
  return tStar;
}

/**
 * A point of both cores' sets (widened by their radius + `verify`) nearest to (px, py) among the
 * crossings of their borders (built at `build`) and the points of either nearest to (px, py);
 * null when none is verified in both.
 */
function meeting(
  a: Core,
  b: Core,
  build: number,
  verify: number,
  px: number,
  py: number,
): [number, number] | null {
  const cand: number[] = [];
  borderCrossings(a, a.rad + build, b, b.rad + build, cand);
  for (const k of [a, b]) {
    widenedNearest(k, build, px, py, q);
    cand.push(q[0] as number, q[1] as number);
  }
  let best: [number, number] | null = null;
  let bestDistance = Number.POSITIVE_INFINITY;
  for (let i = 0; i < cand.length; i += 2) {
    const zx = cand[i] as number;
    const zy = cand[i + 1] as number;
    if (!(coreDistance(a, zx, zy) <= a.rad + verify && coreDistance(b, zx, zy) <= b.rad + verify)) continue;
    const d = length(px - zx, py - zy);
    // Ties to the smaller x, then y: the choice does not depend on the candidates' order.
    if (
      d < bestDistance ||
      (d === bestDistance && best !== null && (zx < best[0] || (zx === best[0] && zy < best[1])))
    ) {
      best = [zx, zy];
      bestDistance = d;
    }
  }
  return best;
}
