/**
 * The crush in line: a proof that a row of discs moving along an axis-parallel line L, between a
 * still end across L and a moving immovable disc P on L, is crushed between them, so that the exact
 * model has infinitely many events before a time t* (used by the trap watch, trapWatch.ts, when no
 * pocket encloses the disc: pocket.ts). Pure functions.
 *
 * No pocket holds such a disc in the plane: it is held on L by symmetry. When the centres, the
 * velocities and accelerations of the discs of the row, P's, and the end (a line across L whose
 * solid part holds the foot of L, a point or an immovable disc at rest centred on L) are exactly
 * symmetric about L, to the bit, every collision among them has its normal along L: in the exact
 * model the discs never leave L, and never pass one another. The row is every finite disc centred
 * on L between the end and P (one or more; they need not touch). If nothing else can touch them
 * (the caller's part: no other obstacle within reach of the stretch of L between the end and P's
 * path, no other finite disc able to reach it or P's path before t*, and nothing changing P's
 * motion before t*, as for a pocket), they are shut in, in one dimension, between the end and P;
 * when P comes within 2 (r'1 + .. + r'n) of the end (r'i = ri (1 - ZENO_TRAP_SLACK), the tests
 * made with the margins of pocket.ts) before its motion law ends, the row cannot fit there:
 * infinitely many events happen before t*.
 *
 * The report waits until P is within ZENO_TRAP_GAP × r of that (r the row's smallest radius), as
 * for a pocket.
 */
import { positionAt, velocityAt } from "../physics/motion.js";
import { ZENO_TRAP_GAP, ZENO_TRAP_SCALE, ZENO_TRAP_SLACK } from "../tolerances.js";
import { closingTime } from "./pocket.js";
import type { Core } from "./pocketGeometry.js";

/** The disc: its centre, velocity and acceleration now, and its radius. */
export interface LineDisc {
  readonly x: number;
  readonly y: number;
  readonly vx: number;
  readonly vy: number;
  readonly ax: number;
  readonly ay: number;
  readonly r: number;
}

/**
 * The sum of the numbers, added in increasing order: the same bits whatever order they come in
 * (the discs' slots follow the order they were added in).
 */
export function orderedSum(values: number[]): number {
  values.sort((a, b) => a - b);
  let sum = 0;
  for (const v of values) sum += v;
  return sum;
}

/** Whether the disc is centred on L (axis k along it, `across` its coordinate across) and keeps to it. */
export function onLine(o: LineDisc, k: number, across: number): boolean {
  return k === 0 ? o.y === across && o.vy === 0 && o.ay === 0 : o.x === across && o.vx === 0 && o.ax === 0;
}

/**
 * The axis of L (0: x, 1: y) when the disc and P (motion mot[at .. at + 7]) keep to one
 * axis-parallel line, to the bit; -1 otherwise. A disc at rest takes P's axis.
 */
export function lineAxis(d: LineDisc, mot: ArrayLike<number>, at: number): number {
  const alongX = d.vy === 0 && d.ay === 0;
  const alongY = d.vx === 0 && d.ax === 0;
  // A disc at rest keeps to both lines through its centre: L is then P's.
  const k = alongX && (!alongY || (mot[at + 4] === 0 && mot[at + 6] === 0)) ? 0 : alongY ? 1 : -1;
  if (k < 0) return -1;
  const j = 1 - k;
  // P on L, moving along it: its position across L never changes.
  const across = j === 1 ? d.y : d.x;
  return mot[at + 1 + j] === across && mot[at + 3 + j] === 0 && mot[at + 5 + j] === 0 ? k : -1;
}

/**
 * Where L (axis k along it, `across` its coordinate across) meets the end, along L (its foot): a
 * point or a disc's centre on L, or a line across L whose solid part holds the foot; NaN for any
 * other core.
 */
export function footOf(end: Core, k: number, across: number): number {
  const j = 1 - k;
  const e1 = k === 0 ? end.x1 : end.y1;
  const e2 = k === 0 ? end.x2 : end.y2;
  const c1 = j === 1 ? end.y1 : end.x1;
  const c2 = j === 1 ? end.y2 : end.x2;
  if (end.kind === "point") return c1 === across ? e1 : Number.NaN;
  // A line across L: the same coordinate along L at both its points, its solid part over L.
  if (e1 !== e2 || c1 === c2) return Number.NaN;
  const lambda = (across - c1) / (c2 - c1);
  if (end.kind !== "line" && !(lambda >= 0)) return Number.NaN;
  if (end.kind === "segment" && !(lambda <= 1)) return Number.NaN;
  return e1;
}

/**
 * The time t* by which the row of discs is crushed in line between the still core `end` and the
 * immovable disc of radius R whose motion is mot[at .. at + 7] (t0, x0, y0, vx, vy, ax, ay, tEnd),
 * proven at `now` as above while P is within ZENO_TRAP_GAP × r of it; NaN when there is no such
 * proof. The row: the disc `d` (the one P strikes; it defines L by keeping to an axis-parallel line)
 * and each disc of `others` centred on L between the end and P; `inRow[i]` receives whether
 * others[i] is one of them (the caller answers for the rest). `hull` receives the triangle holding
 * P's path over [now, t*], and `corridor` the stretch of L the row's centres keep to until then
 * (x0, y0, x1, y1), for the caller's checks.
 */
export function lineCloses(
  now: number,
  d: LineDisc,
  mot: ArrayLike<number>,
  at: number,
  R: number,
  end: Core,
  hull: Float64Array,
  corridor: Float64Array,
  others: readonly LineDisc[] = [],
  inRow: boolean[] = [],
): number {
  // Axis k along L (0: x, 1: y), j across it.
  const k = lineAxis(d, mot, at);
  if (k < 0) return Number.NaN;
  const j = 1 - k;
  const across = j === 1 ? d.y : d.x;
  const along = k === 0 ? d.x : d.y;
  const t0 = mot[at] as number;
  const pAlong = positionAt(
    t0,
    mot[at + 1 + k] as number,
    mot[at + 3 + k] as number,
    mot[at + 5 + k] as number,
    now,
  );
  const vAlong = velocityAt(t0, mot[at + 3 + k] as number, mot[at + 5 + k] as number, now);
  const foot = footOf(end, k, across);
  if (Number.isNaN(foot)) return Number.NaN;
  // The disc between the end and P.
  const side = Math.sign(pAlong - foot);
  const between = (a: number): boolean => Math.sign(a - foot) === side && Math.sign(pAlong - a) === side;
  if (side === 0 || !between(along)) return Number.NaN;
  // The row: its radii's sum and smallest, and the largest magnitude its positions carry.
  const radii = [d.r];
  let r = d.r;
  let size = Math.max(
    Math.abs(along),
    Math.abs(across),
    Math.abs(pAlong),
    Math.abs(foot),
    R,
    end.rad,
    Math.abs(now) * (Math.abs(vAlong) + Math.abs(k === 0 ? d.vx : d.vy)),
  );
  for (let i = 0; i < others.length; i++) {
    const o = others[i] as LineDisc;
    const a = k === 0 ? o.x : o.y;
    const inside = onLine(o, k, across) && between(a);
    inRow[i] = inside;
    if (!inside) continue;
    radii.push(o.r);
    r = Math.min(r, o.r);
    size = Math.max(size, Math.abs(a), Math.abs(now) * Math.abs(k === 0 ? o.vx : o.vy));
  }
  if (!(size <= ZENO_TRAP_SCALE * r)) return Number.NaN;
  const sum = orderedSum(radii);
  const verify = sum * (1 - 1.5 * ZENO_TRAP_SLACK);
  const aim = sum * (1 - 3 * ZENO_TRAP_SLACK);
  const closed = R + end.rad + 2 * verify;
  const gap = Math.abs(pAlong - foot) - closed;
  if (!(gap > 0 && gap <= ZENO_TRAP_GAP * r)) return Number.NaN;
  const zx = k === 0 ? foot : across;
  const zy = k === 0 ? across : foot;
  const tStar = closingTime(now, mot, at, zx, zy, R + end.rad + 2 * aim, closed);
  if (Number.isNaN(tStar)) return Number.NaN;
  // P's path over [now, t*] (its Bézier control points; on L, so a flat triangle).
  const half = 0.5 * (tStar - now);
  const farAlong = positionAt(
    t0,
    mot[at + 1 + k] as number,
    mot[at + 3 + k] as number,
    mot[at + 5 + k] as number,
    tStar,
  );
  const mid = pAlong + vAlong * half;
  const put = (out: Float64Array, i: number, a: number): void => {
    out[i + k] = a;
    out[i + j] = across;
  };
  put(hull, 0, pAlong);
  put(hull, 2, mid);
  put(hull, 4, farAlong);
  // The stretch of L the row keeps to: from the end to P's farthest point from it.
  const far = side > 0 ? Math.max(pAlong, mid, farAlong) : Math.min(pAlong, mid, farAlong);
  put(corridor, 0, foot);
  put(corridor, 2, far);
  return tStar;
}
