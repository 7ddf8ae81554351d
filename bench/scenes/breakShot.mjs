/**
 * Friction billiards break: a rack of 15 discs (r = 1, rows 1…5, neighbours 2·(1 + 1e-6) apart so
 * no pair starts overlapping by round-off) and a cue disc at speed 60 on a 100 × 50 table with
 * cushions; friction field g = 10, μ = 0.2 for every disc (deceleration 2), no gravity.
 * Peers have no sliding-friction model for a top-down table: the harness applies it as a velocity
 * decrement μ·g·dt per step (clamped to zero), which is what a user of those engines writes.
 */
import { boxWalls } from "./walls.mjs";

export function breakShot({ span = 35 } = {}) {
  const r = 1;
  const d = 2 * r * (1 + 1e-6);
  const bodies = [{ id: "cue", x: 25, y: 25, r, m: 1, vx: 60, vy: 0.3, mu: 0.2 }];
  let k = 0;
  for (let row = 0; row < 5; row++) {
    for (let j = 0; j <= row; j++) {
      bodies.push({
        id: `ball${String(++k).padStart(2, "0")}`,
        x: 70 + (row * d * Math.sqrt(3)) / 2,
        y: 25 + (j - row / 2) * d,
        r,
        m: 1,
        vx: 0,
        vy: 0,
        mu: 0.2,
      });
    }
  }
  return {
    id: "break",
    title: "Friction billiards break",
    description: `15-disc rack (r = 1) and a cue disc at (60, 0.3) on a 100 × 50 table; friction field g = 10, μ = 0.2; simulate ${span} s (everything has stopped by 30.1 s).`,
    span,
    g: 10,
    gravity: [0, 0],
    bodies,
    walls: boxWalls(0, 0, 100, 50, 10),
    box: { x0: 0, y0: 0, x1: 100, y1: 50 },
    elastic: false,
    exact: null,
  };
}
