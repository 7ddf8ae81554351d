/**
 * Exact power-of-two scaling of doubles (the solver's normalisation of coefficients and variable).
 *
 * - `exponentOf(x)`: ⌊log2 |x|⌋ for a finite nonzero x (subnormals included), from the bit pattern.
 * - `mulPow2(x, k)`: x·2^k, exact whenever the result is a normal double (or 0/±Infinity beyond the
 *   range), computed in chunks of at most 2^±1000 so no intermediate factor overflows.
 * Only bit manipulation and multiplication by powers of two: bit-identical on every platform.
 */

const f64 = new Float64Array(1);
const u32 = new Uint32Array(f64.buffer);
const HI = (() => {
  f64[0] = 1;
  return u32[1] === 0x3ff00000 ? 1 : 0;
})();

/** 2^j for an integer |j| ≤ 1000 (a normal double), from its bit pattern. */
function pow2(j: number): number {
  u32[HI] = (j + 1023) << 20;
  u32[1 - HI] = 0;
  return f64[0] as number;
}

/** ⌊log2 |x|⌋ for a finite nonzero x. */
export function exponentOf(x: number): number {
  f64[0] = x;
  const biased = ((u32[HI] as number) >>> 20) & 0x7ff;
  if (biased !== 0) return biased - 1023;
  return exponentOf(x * 2 ** 64) - 64; // subnormal
}

/** x·2^k (k an integer), exact when the result is normal. */
export function mulPow2(x: number, k: number): number {
  while (k > 1000) {
    x *= pow2(1000);
    k -= 1000;
  }
  while (k < -1000) {
    x *= pow2(-1000);
    k += 1000;
  }
  return x * pow2(k);
}
