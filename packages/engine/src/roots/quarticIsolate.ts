/**
 * Bernstein subdivision of the quartic hot path (registers: quarticRegisters.ts): isolates each
 * root of p on [lo, lo + h] in a piece of its own.
 *
 * `isolate(loSign)`: from p's Bernstein coefficients b0…b4 and their margin in BC (the exact sign
 * of p at lo, or just after lo when p(lo) = 0, is loSign), de Casteljau halving, left to right, at
 * most MAX_DEPTH levels, the margin grown by ROOTS_SUBDIVISION_MARGIN_GROWTH per halving (a
 * halving's four rounds of averaging add at most 4u·max|b| ≤ 4u·scale). Descartes' rule for the
 * Bernstein basis on each piece whose coefficients all have certified signs: no sign change → no
 * root; exactly one → exactly one simple root inside. Records the one-root pieces in `ones` (per
 * piece: left end s, right end s, where the control polygon crosses zero, all as fractions of h,
 * and the certified sign at the left end); returns their number, or −1 when a piece end is at
 * noise level or MAX_DEPTH is reached undecided (roots closer than h/2^MAX_DEPTH: clusters, double
 * roots). The pieces cover [lo, lo + h], so every root is found exactly once.
 *
 * The halving is written out here (as in quartic.ts and quarticSigns.ts's quarters): this is the
 * subdivision's inner loop, and its halves stay in registers (the right one goes to the stack);
 * halvings through a shared function measured more instructions (see quartic.ts).
 */

import { ROOTS_SUBDIVISION_MARGIN_GROWTH } from "../tolerances.js";
import * as reg from "./quarticRegisters.js";

/** Halving depth limit: pieces of h/256. Deeper cases (near-double roots) take the general path. */
const MAX_DEPTH = 8;
/** Module-local copies (V8 folds a module's own consts, not imports; see quarticRegisters.ts). */
const MARGIN_PER_LEVEL = ROOTS_SUBDIVISION_MARGIN_GROWTH;
const BC = reg.BC;
/** Pending pieces: 5 coefficients, left end s and width w (fractions of h), depth. */
const stack = new Float64Array(8 * (MAX_DEPTH + 2));
const pieces = new Float64Array(4 * 4);
/** The one-root pieces of the last isolate call (4 values each, see above). */
export const ones: Float64Array = pieces;

export function isolate(loSign: number): number {
  const margin = BC[5] as number;
  let b0 = BC[0] as number;
  let b1 = BC[1] as number;
  let b2 = BC[2] as number;
  let b3 = BC[3] as number;
  let b4 = BC[4] as number;
  let sp = 0;
  let nOnes = 0;
  let s = 0;
  let depth = 0;
  let w = 1;
  for (;;) {
    const m = margin * (1 + MARGIN_PER_LEVEL * depth);
    // One sign beyond the margin: no root (the common leaf). Else, with certified ends of
    // opposite signs and certain interior signs, count the sign changes (odd: 1 or 3).
    // The sign of the piece's left end: certified by the margin, or exact at lo (loSign).
    const sl = s === 0 ? loSign : b0 > m ? 1 : b0 < -m ? -1 : 0;
    let leaf =
      sl > 0 ? b1 > m && b2 > m && b3 > m && b4 > m : sl < 0 && b1 < -m && b2 < -m && b3 < -m && b4 < -m;
    let changes = 0;
    if (!leaf) {
      if (sl === 0 || !(Math.abs(b4) > m)) return -1; // a piece end at noise level
      const n0 = sl < 0;
      if (n0 !== b4 < 0 && Math.abs(b1) > m && Math.abs(b2) > m && Math.abs(b3) > m) {
        changes = (n0 !== b1 < 0 ? 1 : 0) + (b1 < 0 !== b2 < 0 ? 1 : 0) + (b2 < 0 !== b3 < 0 ? 1 : 0);
        changes += b3 < 0 !== b4 < 0 ? 1 : 0;
        leaf = changes === 1;
      }
    }
    if (!leaf) {
      if (depth >= MAX_DEPTH) return -1;
      // de Casteljau at the middle: push the right half, continue with the left.
      const l1 = 0.5 * (b0 + b1);
      const m1 = 0.5 * (b1 + b2);
      const m2 = 0.5 * (b2 + b3);
      const r3 = 0.5 * (b3 + b4);
      const l2 = 0.5 * (l1 + m1);
      const m3 = 0.5 * (m1 + m2);
      const r2 = 0.5 * (m2 + r3);
      const l3 = 0.5 * (l2 + m3);
      const r1 = 0.5 * (m3 + r2);
      const mid = 0.5 * (l3 + r1);
      depth++;
      w *= 0.5;
      const e = 8 * sp++;
      stack[e] = mid;
      stack[e + 1] = r1;
      stack[e + 2] = r2;
      stack[e + 3] = r3;
      stack[e + 4] = b4;
      stack[e + 5] = s + w;
      stack[e + 6] = depth;
      stack[e + 7] = w;
      b1 = l1;
      b2 = l2;
      b3 = l3;
      b4 = mid;
      continue;
    }
    if (changes === 1) {
      // Exactly one simple root: the piece, and where its control polygon crosses zero.
      let g: number;
      if (sl < 0 !== b1 < 0) g = b0 / (b0 - b1);
      else if (b1 < 0 !== b2 < 0) g = 1 + b1 / (b1 - b2);
      else if (b2 < 0 !== b3 < 0) g = 2 + b2 / (b2 - b3);
      else g = 3 + b3 / (b3 - b4);
      const o = 4 * nOnes++;
      pieces[o] = s;
      pieces[o + 1] = s + w;
      pieces[o + 2] = s + 0.25 * w * g;
      pieces[o + 3] = sl;
    }
    if (sp === 0) return nOnes;
    const e = 8 * --sp;
    b0 = stack[e] as number;
    b1 = stack[e + 1] as number;
    b2 = stack[e + 2] as number;
    b3 = stack[e + 3] as number;
    b4 = stack[e + 4] as number;
    s = stack[e + 5] as number;
    depth = stack[e + 6] as number;
    w = stack[e + 7] as number;
  }
}
