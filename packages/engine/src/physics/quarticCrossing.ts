/**
 * The first downward crossing of a quartic gap polynomial in a window (pure; no allocation on the hot
 * path). See timeOfImpact.ts for the contract shared by every contact function: a contact counts
 * only while the pair approaches, and a contact under way at lo reports the crossing that led to it.
 * The roots are solved on [0, hi] rather than [lo, hi], so that the time found is a function of the
 * polynomial alone, not of the moment it is evaluated.
 */

import { evalPoly, realRootsInto } from "../roots/realRoots.js";

const coeffs = new Float64Array(5);
/** Roots of the last quartic solved (reused: no allocation per prediction). */
const roots: number[] = [];

/**
 * First tau in [lo, hi] where c0 + c1 t + c2 t^2 + c3 t^3 + c4 t^4 crosses zero downwards; for a
 * contact under way at lo, the crossing that led to it (see crossingUnderWay; the caller clamps).
 * A touching pair whose gap shrinks at lo by no more than `noise` (the rounding of the rate, which
 * the caller bounds) is a graze unless an acceleration presses it in by more than `pressNoise` (the
 * rounding of the second derivative, inputs included; as firstDownCrossingQuadratic).
 * A pair within `band` of touching (the rounding of the gap; CONTACT_BAND) that is pressed together
 * and would not leave the band before its acceleration turns it back (the quadratic model of the gap
 * at lo: the motion there is a rounding's worth) never opens the contact: a resting contact,
 * reported now, at lo, for the response to refuse. The band is -Infinity (no such test) unless the
 * caller gives it: only a contact the response refuses when pressed may use it (a disc without
 * friction against a point), else the same contact would be found again at once.
 */
export function firstDownCrossingQuartic(
  c0: number,
  c1: number,
  c2: number,
  c3: number,
  c4: number,
  lo: number,
  hi: number,
  noise = 0,
  pressNoise = 0,
  band = Number.NEGATIVE_INFINITY,
): number {
  if (!(lo <= hi)) return Number.POSITIVE_INFINITY;
  const fLo = c0 + lo * (c1 + lo * (c2 + lo * (c3 + lo * c4)));
  const dLo = c1 + lo * (2 * c2 + lo * (3 * c3 + lo * 4 * c4));
  const f2Lo = 2 * c2 + lo * (6 * c3 + lo * 12 * c4);
  // In contact and approaching (or resting under an acceleration into the contact) at lo.
  const now = fLo <= 0 && (dLo < -noise || (dLo <= 0 && f2Lo < -pressNoise));
  // Within the band, pressed, and turned back before leaving it: the contact never opens (see above).
  if (!now && fLo <= band && f2Lo < -pressNoise && fLo - (dLo * dLo) / (2 * f2Lo) <= band) return lo;
  // Touching and approaching by no more than the noise, with nothing pressing it in: a graze. With
  // a band (a disc over a point), the contact can close again later without having opened beyond
  // rounding (a disc crossing a peg at about the speed that keeps it on the peg): the first
  // downward crossing after lo is a contact (audit of session 17: it fell through the peg).
  // (With a band, a touching pair whose rate is within the noise either way is a graze too: a rate
  // rounded to +1e-20 left a disc at the critical speed on a peg to sink into it: review.)
  if (!now && fLo <= 0 && dLo <= 0 && band === Number.NEGATIVE_INFINITY) return Number.POSITIVE_INFINITY;
  const graze = !now && fLo <= 0 && dLo <= noise && band !== Number.NEGATIVE_INFINITY;
  coeffs[0] = c0;
  coeffs[1] = c1;
  coeffs[2] = c2;
  coeffs[3] = c3;
  coeffs[4] = c4;
  // Solve on [0, hi] rather than [lo, hi] so that the roots are a pure function of the two motions:
  // the same pair gives the same bits whenever it is (re)computed.
  realRootsInto(coeffs, 0, hi, roots);
  if (now) return crossingUnderWay(lo, c1, c2, c3, c4);
  let first = 0;
  // a graze: not the contact at lo itself
  while (first < roots.length && ((roots[first] as number) < lo || (graze && roots[first] === lo))) first++;
  // A graze whose gap sinks below -band before it opens (the second derivative within rounding of 0
  // at lo, the third into the contact: a disc crossing a peg at exactly the speed that keeps it on
  // the peg) is a contact now, under way at third order: the response refuses it as resting, or
  // reflects it.
  // The same for a pair moving apart from within the band whose crossing back, at third order, is
  // too close to lo for the roots to tell apart (review of session 17: with the peg at y = 63, a
  // disc reflected off it by a rounding's impulse sank 40 % into it).
  const touching = graze || (!now && fLo <= band);
  if (touching && sinksBelow(lo, first < roots.length ? (roots[first] as number) : hi, -band)) return lo;
  if (first > 0 && dLo < -noise) {
    // Approaching, and the last root before lo comes down: the gap can be > 0 at lo only through
    // rounding (it is < 0 until the next root), so the contact is under way since that root.
    const r = roots[first - 1] as number;
    if (c1 + r * (2 * c2 + r * (3 * c3 + r * 4 * c4)) < 0) return r;
  }
  for (let i = first; i < roots.length; i++) {
    const r = roots[i] as number;
    const d = c1 + r * (2 * c2 + r * (3 * c3 + r * 4 * c4));
    if (d < 0) return r;
    if (d === 0) {
      // Derivative vanishes at the root (touching or crossing with zero slope): probe after it.
      const next = i + 1 < roots.length ? (roots[i + 1] as number) : hi;
      // After the last root the sign is the same all the way up: any point past r will do (2r, not
      // r + 1, which has a unit of time and equals r beyond 2^53).
      const probe = Number.isFinite(next) ? 0.5 * (r + next) : r > 0 ? 2 * r : 1;
      if (evalPoly(coeffs, probe) < 0) return r;
    }
  }
  return Number.POSITIVE_INFINITY;
}

const slope = new Float64Array(4);
/** Roots of the derivative of the last quartic solved (reused: no allocation). */
const extrema: number[] = [];

/** Whether the quartic in `coeffs` falls below `floor` at one of its minima in (lo, end). */
function sinksBelow(lo: number, end: number, floor: number): boolean {
  slope[0] = coeffs[1] as number;
  slope[1] = 2 * (coeffs[2] as number);
  slope[2] = 3 * (coeffs[3] as number);
  slope[3] = 4 * (coeffs[4] as number);
  realRootsInto(slope, lo, end, extrema);
  for (let i = 0; i < extrema.length; i++) if (evalPoly(coeffs, extrema[i] as number) < floor) return true;
  return false;
}

/**
 * For a contact under way at lo (the quartic c0 + c1 t + ... + c4 t^4, its roots on [0, hi] in `roots`): the
 * crossing that led to it. If the first root after lo is a downward one, the gap at lo can only be
 * <= 0 through rounding and that root is the crossing (an evaluation before lo found it too);
 * otherwise the last downward root at or before lo; lo when there is none (it started touching).
 */
function crossingUnderWay(lo: number, c1: number, c2: number, c3: number, c4: number): number {
  let best = lo;
  for (let i = 0; i < roots.length; i++) {
    const r = roots[i] as number;
    const d = c1 + r * (2 * c2 + r * (3 * c3 + r * 4 * c4));
    if (r > lo) return d < 0 && best === lo ? r : best;
    if (d < 0) best = r;
  }
  return best;
}
