/**
 * Error of a computed root in ulps, measured with exact arithmetic: the number of doubles between
 * x and the nearest point where the exact polynomial (double coefficients taken exactly) is zero or
 * changes sign, found by a doubling search outward from x then bisection on the ulp index
 * (so errors of 10^10 ulps, like a 1e-6 absolute bisection's, are measured too). Returns Infinity
 * when no sign change lies within 2^62 ulps. `exactPolySign` comes from the engine.
 */
const f64 = new Float64Array(1);
const i64 = new BigInt64Array(f64.buffer);
const SIGN = 1n << 63n;

/** Position of a double on the ordered line of doubles (…, -MIN_VALUE = -1, ±0 = 0, MIN_VALUE = 1, …). */
export function ulpIndex(x) {
  f64[0] = x;
  const b = i64[0];
  return b >= 0n ? b : -(b & (SIGN - 1n));
}

export function fromUlpIndex(k) {
  i64[0] = k >= 0n ? k : BigInt.asIntN(64, -k | SIGN);
  return f64[0];
}

/** |index(a) - index(b)| as a Number. */
export function ulpDistance(a, b) {
  const d = ulpIndex(a) - ulpIndex(b);
  return Number(d < 0n ? -d : d);
}

export function ulpsToSignChange(exactPolySign, coeffs, x) {
  const s0 = exactPolySign(coeffs, x);
  if (s0 === 0) return 0;
  const i0 = ulpIndex(x);
  const differs = (k) => {
    const y = fromUlpIndex(i0 + k);
    return Number.isFinite(y) && exactPolySign(coeffs, y) !== s0;
  };
  let prev = 0n;
  for (let k = 1n; k <= 1n << 62n; k <<= 1n) {
    const up = differs(k);
    const down = differs(-k);
    if (up || down) {
      let best = Number.POSITIVE_INFINITY;
      for (const dir of [up ? 1n : 0n, down ? -1n : 0n]) {
        if (dir === 0n) continue;
        let lo = prev; // same sign at lo (or lo = 0)
        let hi = k; // differs at hi
        while (hi - lo > 1n) {
          const mid = (lo + hi) >> 1n;
          if (differs(dir * mid)) hi = mid;
          else lo = mid;
        }
        best = Math.min(best, Number(hi));
      }
      return best;
    }
    prev = k;
  }
  return Number.POSITIVE_INFINITY;
}
