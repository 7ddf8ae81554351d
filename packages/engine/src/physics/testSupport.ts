/**
 * Exact gap evaluation for the contact tests (test-only; excluded from the build).
 *
 * `exactGapSign(d, u, w, R, tau)`: the exact sign of |d + u tau + w tau^2 / 2|^2 - R^2 with every
 * double taken at its exact value (BigInt dyadic numbers m * 2^e, no rounding), so a test can tell
 * whether a contact time the engine returns is a true crossing of the gap of the given motions.
 */

type Dyadic = { m: bigint; e: number };

const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);

function dyadic(x: number): Dyadic {
  if (!Number.isFinite(x)) throw new RangeError(`exactGapSign: ${x} is not finite`);
  if (x === 0) return { m: 0n, e: 0 };
  f64[0] = x;
  const bits = u64[0] as bigint;
  const biased = Number((bits >> 52n) & 0x7ffn);
  let mant = bits & ((1n << 52n) - 1n);
  let e = -1074;
  if (biased !== 0) {
    mant |= 1n << 52n;
    e = biased - 1075;
  }
  return { m: x < 0 ? -mant : mant, e };
}

function add(a: Dyadic, b: Dyadic): Dyadic {
  if (a.m === 0n) return b;
  if (b.m === 0n) return a;
  const e = Math.min(a.e, b.e);
  return { m: (a.m << BigInt(a.e - e)) + (b.m << BigInt(b.e - e)), e };
}

function mul(a: Dyadic, b: Dyadic): Dyadic {
  return { m: a.m * b.m, e: a.e + b.e };
}

const HALF: Dyadic = { m: 1n, e: -1 };

/** One coordinate of d + u tau + w tau^2 / 2, exactly. */
function coordinate(d: number, u: number, w: number, tau: Dyadic): Dyadic {
  return add(dyadic(d), mul(tau, add(dyadic(u), mul(HALF, mul(dyadic(w), tau)))));
}

/** Exact sign of the gap |d + u tau + w tau^2/2|^2 - R^2 (see the header). */
export function exactGapSign(
  dx: number,
  dy: number,
  ux: number,
  uy: number,
  wx: number,
  wy: number,
  R: number,
  tau: number,
): -1 | 0 | 1 {
  const t = dyadic(tau);
  const x = coordinate(dx, ux, wx, t);
  const y = coordinate(dy, uy, wy, t);
  const r = dyadic(R);
  const gap = add(add(mul(x, x), mul(y, y)), { m: -(r.m * r.m), e: 2 * r.e });
  return gap.m > 0n ? 1 : gap.m < 0n ? -1 : 0;
}
