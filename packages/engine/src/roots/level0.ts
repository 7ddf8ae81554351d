/**
 * Level 0 of realRoots: certified signs of p at lo, the critical points and hi, exact repair around
 * critical points where p is at rounding-noise level, grazing (double) roots, and one certified
 * root per piece whose ends have opposite exact signs (see README.md, steps 5–7).
 *
 * `solveLevel0(P, n, m, lo, hi, splits, ns, out)`: P the (scaled) polynomial of degree n already
 * loaded into certify.ts (and so criticalPoint.ts), m its degree after the degree drop, splits[0..ns) the sorted critical
 * points inside (lo, hi); appends the roots, ascending and distinct, to out. `push` appends one root
 * keeping out strictly increasing. Module scratch arrays, grown on demand.
 */

import { certSign, lastAbsValue, lastWasNoisy, refineRoot } from "./certify.js";
import { criticalPoint, nearestCritical } from "./criticalPoint.js";
import { newtonPlain, quadRootsPlain } from "./newton.js";

let cap = 0;
let pts = new Float64Array(0);
let sgn = new Int8Array(0);
let absv = new Float64Array(0);
let noisy = new Uint8Array(0);
const crit = new Float64Array(2);
const closed = new Float64Array(2);

function ensure(n: number): void {
  if (n <= cap) return;
  cap = n;
  // Room for lo, hi, n − 1 critical points and two exact critical points beside each of them.
  pts = new Float64Array(3 * n + 3);
  sgn = new Int8Array(3 * n + 3);
  absv = new Float64Array(3 * n + 3);
  noisy = new Uint8Array(3 * n + 3);
}

/** Certified signs at lo, the critical points and hi; one refined root per sign change. */
export function solveLevel0(
  P: Float64Array,
  n: number,
  m: number,
  lo: number,
  hi: number,
  splits: Float64Array,
  ns: number,
  out: number[],
): void {
  ensure(n);
  let K = ns + 2;
  pts[0] = lo;
  for (let i = 0; i < ns; i++) pts[i + 1] = splits[i] as number;
  pts[K - 1] = hi;
  let anyNoisy = false;
  for (let i = 0; i < K; i++) {
    sgn[i] = certSign(pts[i] as number);
    absv[i] = lastAbsValue();
    noisy[i] = lastWasNoisy() ? 1 : 0;
    if (noisy[i] === 1 && i > 0 && i < K - 1) anyNoisy = true;
  }
  if (anyNoisy) K = exactCriticalNeighbours(K, n);
  // Grazing (double-root) candidates: noisy critical points with no sign change on either side.
  for (let i = 1; i < K - 1; i++) {
    const s = sgn[i] as number;
    if (noisy[i] === 0 || s === 0 || sgn[i - 1] === -s || sgn[i + 1] === -s) continue;
    if (!criticalPoint(pts[i] as number, pts[i - 1] as number, pts[i + 1] as number, crit)) continue;
    let best = -1;
    let bestAbs = Number.POSITIVE_INFINITY;
    for (let j = 0; j < 2; j++) {
      const x = crit[j] as number;
      const sx = certSign(x);
      if (sx !== s) {
        pts[i] = x; // the exact p reaches zero or crosses it here: ordinary pieces take over
        sgn[i] = sx;
        absv[i] = lastAbsValue();
        noisy[i] = 0;
        best = -2;
        break;
      }
      if (lastAbsValue() < bestAbs) {
        bestAbs = lastAbsValue();
        best = j;
      }
    }
    if (best >= 0) {
      pts[i] = crit[best] as number;
      sgn[i] = 0; // reported as a (double) root; its pieces have no sign change
      absv[i] = bestAbs;
    }
  }
  const quad = n === 2 && m === 2;
  let nq = 0;
  if (quad) nq = quadRootsPlain(P[0] as number, P[1] as number, P[2] as number, lo, hi, closed, 0);
  for (let i = 0; i < K; i++) {
    const a = pts[i] as number;
    const sa = sgn[i] as number;
    if (sa === 0) push(out, a);
    if (i === K - 1) break;
    const sb = sgn[i + 1] as number;
    if (sa === 0 || sb !== -sa) continue;
    const b = pts[i + 1] as number;
    const aa = absv[i] as number;
    const ab = absv[i + 1] as number;
    let x0 = Number.NaN;
    if (quad) {
      for (let j = 0; j < nq; j++)
        if ((closed[j] as number) > a && (closed[j] as number) < b) x0 = closed[j] as number;
    }
    if (Number.isNaN(x0)) {
      const crit = (i > 0 ? 1 : 0) | (i + 1 < K - 1 ? 2 : 0);
      x0 = newtonPlain(P, 0, n, a, b, sa * (aa > 0 ? aa : 1), -sa * (ab > 0 ? ab : 1), crit);
    }
    push(out, refineRoot(a, b, sa, aa, ab, x0));
  }
}

/**
 * Where p is at rounding-noise level at a critical point, plain arithmetic cannot resolve the
 * structure around it (a cluster of roots of p′): the nearest exact sign changes of p′ on each side
 * (found with certified signs, see criticalPoint.ts) are inserted as further piece ends with their exact
 * signs of p, and the search goes on beyond each inserted point while p is still at noise level
 * there, so that no root hides in a non-monotone piece. Returns the new number of points.
 */
function exactCriticalNeighbours(K: number, n: number): number {
  let k = K;
  const cap = 2 * n + 1; // lo, hi, and at most n − 1 structural plus n − 1 exact critical points
  // From the end, so that insertions do not disturb the indices still to visit.
  for (let i = K - 2; i >= 1; i--) {
    if (noisy[i] !== 1) continue;
    // Downwards: insert below, keep going while the inserted point is at noise level.
    let j = i;
    while (k < cap && nearestCritical(pts[j] as number, pts[j - 1] as number, crit)) {
      const y = pick(crit[1] as number, crit[0] as number);
      if (!(y < (pts[j] as number) && y > (pts[j - 1] as number))) break;
      k = insertPoint(k, j, y);
      if (noisy[j] !== 1) break;
    }
    // Upwards from the original point, which moved up by the insertions below it.
    j = i + (k - K);
    while (k < cap && nearestCritical(pts[j] as number, pts[j + 1] as number, crit)) {
      const y = pick(crit[0] as number, crit[1] as number);
      if (!(y > (pts[j] as number) && y < (pts[j + 1] as number))) break;
      k = insertPoint(k, j + 1, y);
      j++;
      if (noisy[j] !== 1) break;
    }
    K = k;
  }
  return k;
}

/** Of the two doubles around a sign change of p′, one where p is exactly 0 if any, else `first`. */
function pick(first: number, second: number): number {
  if (first === second || certSign(first) === 0) return first;
  return certSign(second) === 0 ? second : first;
}

/** Insert x (with its exact sign of p) at index j of the point list of length k; returns k + 1. */
function insertPoint(k: number, j: number, x: number): number {
  for (let t = k; t > j; t--) {
    pts[t] = pts[t - 1] as number;
    sgn[t] = sgn[t - 1] as number;
    absv[t] = absv[t - 1] as number;
    noisy[t] = noisy[t - 1] as number;
  }
  pts[j] = x;
  sgn[j] = certSign(x);
  absv[j] = lastAbsValue();
  noisy[j] = lastWasNoisy() ? 1 : 0;
  return k + 1;
}

export function push(out: number[], x: number): void {
  if (out.length === 0 || x > (out[out.length - 1] as number)) out.push(x + 0); // −0 → +0
}
