/**
 * The root finders compared with the engine's realRoots. All take ascending coefficients of a
 * polynomial of degree ≤ 4 and an interval [lo, hi] and return the sorted distinct real roots in it.
 * - ferrari: closed-form quartic (depressed quartic, Ferrari/Descartes resolvent cubic solved by
 *   Cardano or the trigonometric form), the textbook method; uses Math.cbrt/cos/acos (bench only).
 * - ferrariNewton: the same, each root then polished by two Newton steps on the original polynomial.
 * - bisection: the seed's method: roots of the derivative split the interval into monotone pieces,
 *   each sign-changing piece is halved until it is shorter than an absolute epsilon of 1e-6.
 */

function horner(c, x) {
  let s = c[c.length - 1];
  for (let i = c.length - 2; i >= 0; i--) s = s * x + c[i];
  return s;
}

function quadratic(a, b, c, out) {
  // a x² + b x + c = 0, cancellation-free form
  if (a === 0) {
    if (b !== 0) out.push(-c / b);
    return;
  }
  const disc = b * b - 4 * a * c;
  if (disc < 0) return;
  if (disc === 0) {
    out.push(-b / (2 * a));
    return;
  }
  const q = -0.5 * (b + (b >= 0 ? Math.sqrt(disc) : -Math.sqrt(disc)));
  out.push(q / a);
  if (q !== 0) out.push(c / q);
}

/** Largest real root of m³ + A m² + B m + C. */
function cubicMaxRoot(A, B, C) {
  const P = B - (A * A) / 3;
  const Q = (2 * A * A * A) / 27 - (A * B) / 3 + C;
  const D = (Q * Q) / 4 + (P * P * P) / 27;
  let s;
  if (D >= 0) {
    const sd = Math.sqrt(D);
    s = Math.cbrt(-Q / 2 + sd) + Math.cbrt(-Q / 2 - sd);
  } else {
    const rho = Math.sqrt(-P / 3);
    const cosArg = Math.max(-1, Math.min(1, ((3 * Q) / (2 * P)) * Math.sqrt(-3 / P)));
    s = 2 * rho * Math.cos(Math.acos(cosArg) / 3);
  }
  return s - A / 3;
}

function cubicRoots(a, b, c, d, out) {
  // a x³ + b x² + c x + d (a ≠ 0): all real roots
  const A = b / a;
  const B = c / a;
  const C = d / a;
  const P = B - (A * A) / 3;
  const Q = (2 * A * A * A) / 27 - (A * B) / 3 + C;
  const D = (Q * Q) / 4 + (P * P * P) / 27;
  if (D > 0) {
    const sd = Math.sqrt(D);
    out.push(Math.cbrt(-Q / 2 + sd) + Math.cbrt(-Q / 2 - sd) - A / 3);
  } else if (P === 0) {
    out.push(-A / 3);
  } else {
    const rho = Math.sqrt(-P / 3);
    const phi = Math.acos(Math.max(-1, Math.min(1, ((3 * Q) / (2 * P)) * Math.sqrt(-3 / P))));
    for (let k = 0; k < 3; k++) out.push(2 * rho * Math.cos((phi - 2 * Math.PI * k) / 3) - A / 3);
  }
}

function finish(all, lo, hi) {
  const inside = all.filter((x) => x >= lo && x <= hi).sort((a, b) => a - b);
  const res = [];
  for (const x of inside) if (res.length === 0 || x !== res[res.length - 1]) res.push(x);
  return res;
}

function ferrariAll(c) {
  let n = c.length - 1;
  while (n > 0 && c[n] === 0) n--;
  const out = [];
  if (n <= 2) {
    quadratic(c[2] ?? 0, c[1] ?? 0, c[0], out);
    return out;
  }
  if (n === 3) {
    cubicRoots(c[3], c[2], c[1], c[0], out);
    return out;
  }
  const a = c[3] / c[4];
  const b = c[2] / c[4];
  const cc = c[1] / c[4];
  const d = c[0] / c[4];
  const a2 = a * a;
  const p = b - (3 * a2) / 8;
  const q = cc - (a * b) / 2 + (a2 * a) / 8;
  const r = d - (a * cc) / 4 + (a2 * b) / 16 - (3 * a2 * a2) / 256;
  const shift = -a / 4;
  const ys = [];
  if (q === 0) {
    const zs = [];
    quadratic(1, p, r, zs);
    for (const z of zs) {
      if (z >= 0) {
        const s = Math.sqrt(z);
        ys.push(s, -s);
      }
    }
  } else {
    const m = cubicMaxRoot(p, (p * p) / 4 - r, (-q * q) / 8);
    if (m > 0) {
      const s = Math.sqrt(2 * m);
      const t = q / (2 * s);
      quadratic(1, -s, p / 2 + m + t, ys);
      quadratic(1, s, p / 2 + m - t, ys);
    }
  }
  for (const y of ys) out.push(y + shift);
  return out;
}

export function ferrari(coeffs, lo, hi) {
  return finish(ferrariAll(coeffs), lo, hi);
}

export function ferrariNewton(coeffs, lo, hi) {
  const n = coeffs.length;
  const raw = ferrariAll(coeffs);
  for (let k = 0; k < raw.length; k++) {
    let x = raw[k];
    for (let it = 0; it < 2; it++) {
      let f = coeffs[n - 1];
      let df = 0;
      for (let i = n - 2; i >= 0; i--) {
        df = df * x + f;
        f = f * x + coeffs[i];
      }
      if (df === 0 || f === 0) break;
      x -= f / df;
    }
    raw[k] = x;
  }
  return finish(raw, lo, hi);
}

const EPS = 1e-6;

function bisectRoots(c, lo, hi) {
  let n = c.length - 1;
  while (n >= 0 && c[n] === 0) n--;
  if (n <= 0) return [];
  const cc = c.slice(0, n + 1);
  if (n === 1) {
    const x = -cc[0] / cc[1];
    return x >= lo && x <= hi ? [x] : [];
  }
  const d = [];
  for (let i = 1; i <= n; i++) d.push(i * cc[i]);
  const pts = [lo, ...bisectRoots(d, lo, hi).filter((x) => x > lo && x < hi), hi];
  const out = [];
  let a = pts[0];
  let fa = horner(cc, a);
  if (fa === 0) out.push(a);
  for (let i = 1; i < pts.length; i++) {
    const b0 = pts[i];
    const fb = horner(cc, b0);
    if (fb === 0) out.push(b0);
    else if (fa !== 0 && fa < 0 !== fb < 0) {
      let x0 = a;
      let x1 = b0;
      let f0 = fa;
      while (x1 - x0 > EPS) {
        const m = 0.5 * (x0 + x1);
        if (m <= x0 || m >= x1) break;
        const fm = horner(cc, m);
        if (fm < 0 === f0 < 0) {
          x0 = m;
          f0 = fm;
        } else x1 = m;
      }
      out.push(0.5 * (x0 + x1));
    }
    a = b0;
    fa = fb;
  }
  return out;
}

export function bisection(coeffs, lo, hi) {
  return finish(bisectRoots(Array.from(coeffs), lo, hi), lo, hi);
}
