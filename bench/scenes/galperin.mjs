/**
 * Galperin's π billiard (shared/reference-cases.md): a wall x = 0, a disc of mass 1 at rest at
 * x = 5, a disc of mass 100^(n−1) at x = 10 moving at (−1, 0); r = 1, frictionless. The number of
 * collisions (disc–disc plus disc–wall) is the first n digits of π.
 */
export const PI_DIGITS = "314159265358979";

export function galperinCount(digits) {
  return Number(PI_DIGITS.slice(0, digits));
}

/** Span: 2 s past the last collision of the 1D reference loop (so every collision is inside it). */
export function galperin(digits, { span = Math.ceil(galperin1D(digits).lastTime) + 2 } = {}) {
  return {
    id: `galperin-${digits}`,
    title: `Galperin's billiard, ${digits} digit${digits > 1 ? "s" : ""}`,
    description: `wall x = 0; disc m = 1 at x = 5 at rest; disc m = 100^${digits - 1} at x = 10, v = (−1, 0); r = 1; simulate ${span} s. Exact collision count ${galperinCount(digits)}.`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies: [
      { id: "light", x: 5, y: 0, r: 1, m: 1, vx: 0, vy: 0, mu: 0 },
      { id: "heavy", x: 10, y: 0, r: 1, m: 100 ** (digits - 1), vx: -1, vy: 0, mu: 0 },
    ],
    walls: [{ id: "wall", p1: [0, -1], p2: [0, 1], kind: "line", inside: [1, 0], thickness: 10 }],
    box: null,
    elastic: true,
    /** Escaped: the light disc went through the wall or through the heavy disc. */
    escaped: (s) => (s[0].x < 0 || s[0].x > s[1].x ? 1 : 0),
    exact: { collisions: galperinCount(digits) },
  };
}

/**
 * The same billiard as a plain 1D event loop in doubles (wall contact at x = 1, disc contact at a
 * gap of 2): the collision count and the time of the last collision. Used to size the span that
 * the step-based peers simulate, so that every collision falls inside it.
 */
export function galperin1D(digits) {
  const M = 100 ** (digits - 1);
  let xl = 5;
  let xh = 10;
  let vl = 0;
  let vh = -1;
  let t = 0;
  let count = 0;
  for (;;) {
    const tw = vl < 0 ? (xl - 1) / -vl : Number.POSITIVE_INFINITY;
    const td = vl > vh ? (xh - xl - 2) / (vl - vh) : Number.POSITIVE_INFINITY;
    const dt = Math.min(tw, td);
    if (dt === Number.POSITIVE_INFINITY) return { count, lastTime: t };
    xl += vl * dt;
    xh += vh * dt;
    t += dt;
    count++;
    if (tw <= td) vl = -vl;
    else {
      const nl = ((1 - M) * vl + 2 * M * vh) / (1 + M);
      vh = ((M - 1) * vh + 2 * vl) / (1 + M);
      vl = nl;
    }
  }
}
