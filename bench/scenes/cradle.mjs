/**
 * Newton's cradle (shared/reference-cases.md): five discs r = 1 touching at x = 0, 2, 4, 6, 8 on
 * y = 0 and a striker at x = −6 moving at (4, 0). Exact outcome: the striker stops at x = −2 at
 * t = 1, the row stays, the last disc leaves x = 8 at t = 1 with velocity (4, 0).
 */
export function cradle({ span = 3 } = {}) {
  const bodies = [{ id: "c0", x: -6, y: 0, r: 1, m: 1, vx: 4, vy: 0, mu: 0 }];
  for (let i = 0; i < 5; i++)
    bodies.push({ id: `c${i + 1}`, x: 2 * i, y: 0, r: 1, m: 1, vx: 0, vy: 0, mu: 0 });
  const final = [{ x: -2, y: 0, vx: 0, vy: 0 }];
  for (let i = 0; i < 4; i++) final.push({ x: 2 * i, y: 0, vx: 0, vy: 0 });
  final.push({ x: 8 + 4 * (span - 1), y: 0, vx: 4, vy: 0 });
  return {
    id: "cradle",
    title: "Newton's cradle",
    description: `5 touching discs r = 1 at x = 0…8, striker at x = −6 with v = (4, 0); simulate ${span} s. Exact: only the last disc moves, at (4, 0).`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies,
    walls: [],
    box: null,
    elastic: true,
    exact: { final, collisions: 5 },
  };
}
