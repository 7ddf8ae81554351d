/**
 * Safeguarded Halley iteration of the quartic hot path (registers: quarticRegisters.ts).
 *
 * `halley(off, critical)`: newtonPlain (newton.ts) on the polynomial Q[off..off+4] (off = 0 for p,
 * P1 for p′, whose top coefficient is 0) over the bracket H[0..1] with plain values H[2..3] of
 * opposite signs, started from H[4] when inside; else, when an end is a critical point (critical:
 * 1 = a, 2 = b), from newton.ts's quadratic model there; else regula falsi; else the split point.
 * The same steps, safeguards and stopping rule as newtonPlain, except that it stops once Halley's
 * step is a small correction (ROOTS_HOT_HALLEY_STOP: refine's compensated Newton step covers the
 * rest). The result into H[5]. Throws RootSolverError after ROOTS_MAX_ITERATIONS steps.
 */

import { ROOTS_HOT_HALLEY_STOP, ROOTS_MAX_ITERATIONS } from "../tolerances.js";
import { RootSolverError, splitPoint } from "./bracket.js";
import * as reg from "./quarticRegisters.js";

/** Module-local copies (V8 folds a module's own consts, not imports; see quarticRegisters.ts). */
const Q = reg.Q;
const H = reg.H;
const EARLY = ROOTS_HOT_HALLEY_STOP;
const MAX_IT = ROOTS_MAX_ITERATIONS;
/** As newton.ts: Halley's step for at most this many iterations, Newton's after. */
const NEWTON_STEPS = 20;

export function halley(off: number, critical: number): void {
  const c0 = Q[off] as number;
  const c1 = Q[off + 1] as number;
  const c2 = Q[off + 2] as number;
  const c3 = Q[off + 3] as number;
  const c4 = Q[off + 4] as number;
  let a = H[0] as number;
  let b = H[1] as number;
  const fa = H[2] as number;
  const fb = H[3] as number;
  const guess = H[4] as number;
  const aNeg = fa < 0;
  let x = guess;
  if (!(x > a && x < b) && critical !== 0) {
    // newton.ts's start at a critical end e (p′(e) = 0): p(e + δ) ≈ p(e) + p″(e)δ²/2.
    const e = critical === 1 ? a : b;
    let f = c4 * e + c3;
    let d1 = c4 * e + f;
    let d2 = c4;
    f = f * e + c2;
    d2 = d2 * e + d1;
    d1 = d1 * e + f;
    d2 = d2 * e + d1;
    const q = -(critical === 1 ? fa : fb) / d2;
    if (q > 0) x = critical === 1 ? a + Math.sqrt(q) : b - Math.sqrt(q);
  }
  if (!(x > a && x < b)) x = a - fa * ((b - a) / (fb - fa));
  if (!(x > a && x < b)) x = splitPoint(a, b);
  let dxOld = Number.POSITIVE_INFINITY;
  let dx = Number.POSITIVE_INFINITY;
  for (let it = 0; it < MAX_IT; it++) {
    // p, p′ and p″/2 at x in one Horner pass (newtonPlain's loop unrolled; the first line is the
    // x³ step, after which p″/2 = c4 and p′ = c4·x + (c4·x + c3)).
    let f = c4 * x + c3;
    let d1 = c4 * x + f;
    let d2 = c4;
    f = f * x + c2;
    d2 = d2 * x + d1;
    d1 = d1 * x + f;
    f = f * x + c1;
    d2 = d2 * x + d1;
    d1 = d1 * x + f;
    f = f * x + c0;
    if (f === 0) {
      H[5] = x;
      return;
    }
    if (f < 0 === aNeg) a = x;
    else b = x;
    // Halley's step where it is a small correction of Newton's, Newton's elsewhere (newton.ts).
    const fd2 = f * d2;
    const d11 = d1 * d1;
    const hal = Math.abs(fd2) <= 0.5 * d11;
    const step = hal && it < NEWTON_STEPS ? (f * d1) / (d11 - fd2) : f / d1;
    const as = Math.abs(step);
    const ax = Math.abs(x);
    let xn = x - step;
    if (hal && Math.abs(f) <= EARLY * ax * Math.abs(d1) && xn >= a && xn <= b) {
      H[5] = xn;
      return;
    }
    if (it >= NEWTON_STEPS || !(xn > a && xn < b) || as > 0.5 * Math.abs(dxOld)) {
      xn = splitPoint(a, b);
      if (xn === a) {
        H[5] = x;
        return;
      }
    }
    dxOld = dx;
    dx = xn - x;
    x = xn;
  }
  throw new RootSolverError(`newton: no convergence in ${MAX_IT} iterations on [${a}, ${b}]`);
}
