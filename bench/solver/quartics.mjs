/**
 * The polynomials of the solver benchmark.
 * - collisionQuartics(count, seed): |d + u t + w t²/2|² − R² for random relative position d
 *   (|d_i| ≤ 10), velocity u (|u_i| ≤ 10), acceleration w (|w_i| ≤ 2, never both zero), contact
 *   distance R ∈ [0.5, 3]; interval [0, 10]. Ascending coefficients.
 * - hardQuartics(): hand-picked hard cases of the kinds used in published quartic test sets
 *   (Strobach 2010, Flocke 2015): extreme root spread, clustered roots, double and near-double roots,
 *   grazing contact, no real roots near a tangency. Coefficients are expanded exactly (BigInt) from
 *   dyadic roots and rounded once to doubles; `exactRoots` lists roots that stay exact roots of the
 *   double coefficients (so errors at double roots, where the sign does not change, can be measured).
 */
import { lcg } from "../lib/lcg.mjs";

export function collisionQuartic(dx, dy, ux, uy, wx, wy, R) {
  return [
    dx * dx + dy * dy - R * R,
    2 * (dx * ux + dy * uy),
    ux * ux + uy * uy + dx * wx + dy * wy,
    ux * wx + uy * wy,
    (wx * wx + wy * wy) / 4,
  ];
}

export function collisionQuartics(count, seed = 7) {
  const rnd = lcg(seed);
  const s = (k) => (2 * rnd() - 1) * k;
  const list = [];
  while (list.length < count) {
    const wx = s(2);
    const wy = s(2);
    if (wx === 0 && wy === 0) continue;
    list.push(collisionQuartic(s(10), s(10), s(10), s(10), wx, wy, 0.5 + 2.5 * rnd()));
  }
  return { polys: list, lo: 0, hi: 10 };
}

const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);
/** A finite double as [BigInt mantissa, exponent]. */
function dyadic(x) {
  if (x === 0) return [0n, 0];
  f64[0] = Math.abs(x);
  const bits = u64[0];
  const biased = Number(bits >> 52n);
  let m = bits & ((1n << 52n) - 1n);
  let e;
  if (biased === 0) e = -1074;
  else {
    m |= 1n << 52n;
    e = biased - 1075;
  }
  return [x < 0 ? -m : m, e];
}

/** Ascending double coefficients of lead·Π(t − r_i), expanded exactly and rounded once each. */
export function fromRoots(roots, lead = 1) {
  const ds = roots.map(dyadic);
  const E = Math.min(...ds.map(([, e]) => e));
  const ms = ds.map(([m, e]) => m << BigInt(e - E));
  let poly = [1n]; // ascending, integer coefficients in units of 2^(E·(n−i))
  for (const m of ms) {
    const next = new Array(poly.length + 1).fill(0n);
    for (let i = 0; i < poly.length; i++) {
      next[i + 1] += poly[i];
      next[i] -= m * poly[i];
    }
    poly = next;
  }
  const n = roots.length;
  return poly.map((c, i) => lead * Number(c) * 2 ** (E * (n - i)));
}

/** Multiply two ascending polynomials given as doubles exactly representable products (small ints). */
function mul(a, b) {
  const out = new Array(a.length + b.length - 1).fill(0);
  for (let i = 0; i < a.length; i++) for (let j = 0; j < b.length; j++) out[i + j] += a[i] * b[j];
  return out;
}

export function hardQuartics() {
  const e12 = 2 ** -12;
  const cluster = [1, 1 + e12, 1 + 2 * e12, 1 + 3 * e12];
  const nearDouble = [1, 1 + 2 ** -30, 2, 3];
  return [
    {
      id: "spread-1e9",
      note: "roots 1, 1e3, 1e6, 1e9",
      coeffs: fromRoots([1, 1e3, 1e6, 1e9]),
      expected: 4,
      lo: 0,
      hi: 2e9,
    },
    {
      id: "spread-1e-6",
      note: "roots 1e-6, 1e-3, 1, 1e3",
      coeffs: fromRoots([1e-6, 1e-3, 1, 1e3]),
      expected: 4,
      lo: 0,
      hi: 2e3,
    },
    {
      id: "cluster",
      note: "roots 1, 1 + 2^-12, 1 + 2^-11, 1 + 3·2^-12 (exact)",
      coeffs: fromRoots(cluster),
      exactRoots: cluster,
      expected: 4,
      lo: 0,
      hi: 2,
    },
    {
      id: "near-double",
      note: "roots 1, 1 + 2^-30, 2, 3 (exact)",
      coeffs: fromRoots(nearDouble),
      exactRoots: nearDouble,
      expected: 4,
      lo: 0,
      hi: 4,
    },
    {
      id: "double",
      note: "roots 1 (double), 2, 3 (exact)",
      coeffs: fromRoots([1, 1, 2, 3]),
      exactRoots: [1, 2, 3],
      expected: 3,
      lo: 0,
      hi: 4,
    },
    {
      id: "two-doubles",
      note: "roots 1 and 2, both double (exact)",
      coeffs: fromRoots([1, 1, 2, 2]),
      exactRoots: [1, 2],
      expected: 2,
      lo: 0,
      hi: 4,
    },
    {
      id: "grazing",
      note: "disc passing exactly at the contact distance: |(−5, 1) + (1, 0)t|² − 1 = (t − 5)²",
      coeffs: collisionQuartic(-5, 1, 1, 0, 0, 0, 1),
      exactRoots: [5],
      expected: 1,
      lo: 0,
      hi: 10,
    },
    {
      id: "near-grazing",
      note: "the same with R = 1 + 2^-26: two roots about 3.5e-4 apart",
      coeffs: collisionQuartic(-5, 1, 1, 0, 0, 0, 1 + 2 ** -26),
      expected: 2,
      lo: 0,
      hi: 10,
    },
    {
      id: "no-real-near-tangent",
      note: "((t − 1)² + 2^-40)((t − 2)² + 1): no real root, a near-zero minimum at t = 1",
      coeffs: mul([1 + 2 ** -40, -2, 1], [5, -4, 1]),
      expected: 0,
      lo: 0,
      hi: 4,
    },
    {
      id: "fast-approach",
      note: "collision quartic, relative speed 1e6, contact distance 0.5 over [0, 1]: roots near 1e-6 and 2e-6",
      coeffs: collisionQuartic(-1.5, 0, 1e6, 0, -3, 0.5, 0.5),
      expected: 2,
      lo: 0,
      hi: 1,
    },
  ];
}
