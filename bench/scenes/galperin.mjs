/**
 * Galperin's π billiard (shared/reference-cases.md): a wall x = 0, a disc of mass 1 at rest at
 * x = 5, a disc of mass 100^(n−1) at x = 10 moving at (−1, 0); r = 1, frictionless. The number of
 * collisions (disc–disc plus disc–wall) is the first n digits of π.
 */
export const PI_DIGITS = "314159265358979";

export function galperinCount(digits) {
  return Number(PI_DIGITS.slice(0, digits));
}

export function galperin(digits, { span = 20 } = {}) {
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
