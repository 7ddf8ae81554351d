/**
 * Seeded linear congruential generator (Numerical Recipes constants), shared by every benchmark so
 * scenes and random polynomials are identical across engines and runs.
 * lcg(seed)() returns a float in [0, 1) with 32 random bits.
 */
export function lcg(seed) {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 4294967296;
  };
}
