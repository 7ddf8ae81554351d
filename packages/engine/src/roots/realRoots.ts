/**
 * realRoots(coeffs, lo, hi): the distinct real roots of c0 + c1 t + c2 t² + … in [lo, hi], sorted.
 * Method: roots of the derivative split [lo, hi] into monotone pieces; each piece whose end values
 * differ in sign holds exactly one root, found by bisection. (First simple version; to be refined.)
 */

/** Horner evaluation of c0 + c1 x + … (ascending coefficients). */
export function evalPoly(coeffs: ArrayLike<number>, x: number): number {
  let n = coeffs.length - 1;
  if (n < 0) return 0;
  let s = coeffs[n] as number;
  while (n > 0) {
    n--;
    s = s * x + (coeffs[n] as number);
  }
  return s;
}

function bisect(c: number[], a: number, b: number, fa: number): number {
  for (let i = 0; i < 2100; i++) {
    const m = 0.5 * (a + b);
    if (m <= a || m >= b) break;
    const fm = evalPoly(c, m);
    if (fm === 0) return m;
    if (fm < 0 === fa < 0) {
      a = m;
      fa = fm;
    } else b = m;
  }
  return 0.5 * (a + b);
}

function rootsOf(c: number[], lo: number, hi: number): number[] {
  let n = c.length - 1;
  while (n >= 0 && c[n] === 0) n--;
  if (n < 0) return [lo]; // identically zero: report lo (degenerate)
  const cc = c.slice(0, n + 1);
  if (n === 0) return [];
  if (n === 1) {
    const r = -(cc[0] as number) / (cc[1] as number);
    return r >= lo && r <= hi ? [r] : [];
  }
  const d: number[] = [];
  for (let i = 1; i <= n; i++) d.push(i * (cc[i] as number));
  const crit = rootsOf(d, lo, hi).filter((x) => x > lo && x < hi);
  const pts = [lo, ...crit, hi];
  const out: number[] = [];
  let a = pts[0] as number;
  let fa = evalPoly(cc, a);
  if (fa === 0) out.push(a);
  for (let i = 1; i < pts.length; i++) {
    const b = pts[i] as number;
    const fb = evalPoly(cc, b);
    if (fb === 0) out.push(b);
    else if (fa !== 0 && fa < 0 !== fb < 0) out.push(bisect(cc, a, b, fa));
    a = b;
    fa = fb;
  }
  const res: number[] = [];
  for (const x of out) if (res.length === 0 || x !== res[res.length - 1]) res.push(x);
  return res;
}

/** Distinct real roots in [lo, hi], ascending. */
export function realRoots(coeffs: ArrayLike<number>, lo: number, hi: number): number[] {
  if (!(lo <= hi)) return [];
  return rootsOf(Array.from(coeffs), lo, hi);
}
