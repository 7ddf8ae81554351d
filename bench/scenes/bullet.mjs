/**
 * A fast disc (r = 0.5) fired at a thin wall (a segment x = 0, |y| ≤ 2; peers get a box 1e-3
 * thick) from x = −1 at `speed`. Exact: it reflects at t = 0.5/speed and ends at x = 1 − 2r − speed·T.
 * Escaped = found on the far side (x > 0) at the end.
 */
export function bullet(speed, { span = 1 } = {}) {
  const r = 0.5;
  return {
    id: `bullet-${speed}`,
    title: `Fast disc at a thin wall, ${speed} units/s`,
    description: `disc r = ${r} at x = −1 moving at (${speed}, 0) towards a segment x = 0, −2 ≤ y ≤ 2 (peers: a box 0.001 thick); simulate ${span} s.`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies: [{ id: "bullet", x: -1, y: 0, r, m: 1, vx: speed, vy: 0, mu: 0 }],
    walls: [{ id: "thin", p1: [0, -2], p2: [0, 2], kind: "segment", inside: [-1, 0], thickness: 1e-3 }],
    box: null,
    elastic: true,
    escaped: (s) => (s[0].x > 0 ? 1 : 0),
    exact: { final: [{ x: 1 - 2 * r - speed * span, y: 0, vx: -speed, vy: 0 }], collisions: 1 },
  };
}
