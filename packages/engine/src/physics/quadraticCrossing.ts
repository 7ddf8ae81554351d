/**
 * The first downward crossing of a quadratic gap in a window (pure; no allocation on the hot path):
 * the disc–disc gap without relative acceleration, the disc–line gap, a coordinate leaving its
 * cell. See timeOfImpact.ts for the contract shared by every contact function: a contact counts only
 * while the pair approaches, and a contact under way at lo reports the crossing that led to it.
 */

/**
 * First tau in [lo, hi] where h(tau) = c0 + c1 tau + c2 tau^2 crosses zero downwards. When h(lo) <= 0
 * and h is decreasing there (or resting with h'' < 0) and `immediate` is true, the contact is under
 * way: its downward root (at or before lo up to rounding; the caller clamps), or lo when h has no
 * root. Roots use the cancellation-free closed form; `discriminant`, when given, is c1^2 - 4 c2 c0
 * computed by the caller in a form that does not cancel. A touching pair whose h'(lo) is negative
 * by no more than `noise` (the rounding of h' the caller bounds) does not count as approaching,
 * unless an acceleration presses it in (c2 < 0): its response could not tell that approach from
 * none, and the same contact would be found again at once for ever (a Zeno state in no time).
 * Likewise an acceleration presses it in only when h'' < -`pressNoise` (the rounding of c2, inputs
 * included, which the caller bounds): below that the press is the rounding of an acceleration along
 * the contact (friction on a disc sliding past another or along a line).
 */
export function firstDownCrossingQuadratic(
  c0: number,
  c1: number,
  c2: number,
  lo: number,
  hi: number,
  immediate = true,
  discriminant = Number.NaN,
  noise = 0,
  pressNoise = 0,
  band = Number.NEGATIVE_INFINITY,
): number {
  const a = DOWN_ARGS;
  a[0] = c0;
  a[1] = c1;
  a[2] = c2;
  a[3] = lo;
  a[4] = hi;
  a[5] = discriminant;
  a[6] = noise;
  a[7] = pressNoise;
  a[9] = band;
  downCrossing(immediate);
  return a[8] as number;
}

/**
 * The doubles of `downCrossing`: c0, c1, c2, lo, hi, discriminant, noise, pressNoise in, the result
 * at [8], band in at [9]. The solver is too large for V8 to inline into its hot callers (pair tests, cell exits),
 * and a double passed to or returned from a call that is not inlined is boxed: a heap allocation
 * each, about 40 per collision in a gas. Through this array they cross the call unboxed, and the
 * small wrapper above, which V8 does inline, keeps the pure signature.
 */
const DOWN_ARGS = new Float64Array(10);

/** firstDownCrossingQuadratic on DOWN_ARGS. */
function downCrossing(immediate: boolean): void {
  const a = DOWN_ARGS;
  const c0 = a[0] as number;
  const c1 = a[1] as number;
  const c2 = a[2] as number;
  const lo = a[3] as number;
  const hi = a[4] as number;
  const noise = a[6] as number;
  a[8] = Number.POSITIVE_INFINITY;
  if (!(lo <= hi)) return;
  const hLo = c0 + lo * (c1 + lo * c2);
  const dLo = c1 + 2 * c2 * lo;
  // Touching and approaching (or resting under an acceleration into the contact) at lo.
  if (hLo <= 0 && immediate && (dLo < -noise || (dLo <= 0 && c2 < -(a[7] as number)))) {
    a[8] = quadraticUnderWay(c0, c1, c2, lo, hi, a[5] as number);
    return;
  }
  // Touching and approaching by no more than the noise, with nothing pressing it in: a graze.
  if (hLo <= 0 && immediate && dLo <= 0) return;
  // Touching (within the band: a rounding above, or inside) and at rest or moving away, but turned
  // back for good (approaching at hi: not a friction stop) before the gap leaves the band: the
  // contact never opens, a resting contact (CONTACT_BAND). The contact is now (at the motion's
  // start, where it is first seen), and the response refuses it.
  const band = a[9] as number;
  if (
    immediate &&
    hLo <= band &&
    c2 < -(a[7] as number) &&
    hLo - (dLo * dLo) / (4 * c2) <= band &&
    c1 + 2 * c2 * hi < -noise
  ) {
    a[8] = lo;
    return;
  }
  // Convex and not decreasing at lo: it never comes down again (the common, cheap rejection).
  if (c2 >= 0 && dLo >= 0) return;
  if (c2 === 0) {
    const r = -c0 / c1;
    if (r >= lo && r <= hi) a[8] = r;
    return;
  }
  const given = a[5] as number;
  const disc = Number.isNaN(given) ? c1 * c1 - 4 * c2 * c0 : given;
  if (disc < 0) return;
  const sq = Math.sqrt(disc);
  const q = c1 >= 0 ? -0.5 * (c1 + sq) : -0.5 * (c1 - sq);
  if (q === 0) return; // c0 = c1 = 0: touching with zero slope, handled above
  let r1 = q / c2;
  let r2 = c0 / q;
  if (r1 > r2) {
    const t = r1;
    r1 = r2;
    r2 = t;
  }
  // The derivative at a root of a quadratic is +-sqrt(disc): it is negative at the smaller root
  // when c2 > 0 and at the larger root when c2 < 0.
  const down = c2 > 0 ? r1 : r2;
  if (down < lo) {
    // Past the crossing already: a round-off overlap. Approaching now means the contact is under
    // way since the crossing (the caller clamps it to now).
    if (dLo < -noise && immediate) a[8] = down;
    return;
  }
  if (disc === 0) return; // tangency without crossing: a graze, no impulse
  if (down <= hi) a[8] = down;
}

/**
 * A contact under way at lo (h(lo) <= 0, approaching): the downward root of h, at or before lo up
 * to rounding (there is only one), or lo when h has none (it started touching).
 */
function quadraticUnderWay(
  c0: number,
  c1: number,
  c2: number,
  lo: number,
  hi: number,
  discriminant: number,
): number {
  if (c2 === 0) {
    const r = -c0 / c1; // c1 < 0 here
    return r <= hi ? r : lo;
  }
  const disc = Number.isNaN(discriminant) ? c1 * c1 - 4 * c2 * c0 : discriminant;
  if (disc < 0) return lo;
  const sq = Math.sqrt(disc);
  const q = c1 >= 0 ? -0.5 * (c1 + sq) : -0.5 * (c1 - sq);
  if (q === 0) return lo;
  const r1 = q / c2;
  const r2 = c0 / q;
  const down = c2 > 0 ? Math.min(r1, r2) : Math.max(r1, r2);
  return down <= hi ? down : lo;
}
