/**
 * Brownian motion: one heavy disc of radius `bigR` (mass bigR², at rest) at the centre of a square
 * box, among `n` discs of radius 1 and mass 1 at speed `speed` in seeded random directions, on a grid
 * that leaves the big disc clear; 10 % packing counting the big disc; elastic, frictionless. Used for
 * the engine's mixed-radii rows: a disc far larger than the rest is what used to size the grid's
 * cells for everyone.
 */
import { lcg } from "../lib/lcg.mjs";
import { boxWalls } from "./walls.mjs";

export function bigDiscGas({ n = 10000, bigR = 20, packing = 0.1, speed = 10, seed = 3, span = 1e9 } = {}) {
  const side = Math.sqrt((Math.PI * (n + bigR * bigR)) / packing);
  const c = side / 2;
  // Grid sites with room for n discs outside the big one (3.2 radii apart at the least).
  const k = Math.ceil(Math.sqrt(n * 1.6));
  const cell = side / k;
  if (cell <= 2.2) throw new Error(`bigDiscGas: packing ${packing} too dense for a grid start`);
  const rnd = lcg(seed);
  const bodies = [{ id: "big", x: c, y: c, r: bigR, m: bigR * bigR, vx: 0, vy: 0, mu: 0 }];
  for (let i = 0; i < k * k && bodies.length <= n; i++) {
    const x = ((i % k) + 0.5) * cell;
    const y = (Math.floor(i / k) + 0.5) * cell;
    const dx = x - c;
    const dy = y - c;
    if (dx * dx + dy * dy < (bigR + 2) * (bigR + 2)) continue;
    const a = 2 * Math.PI * rnd();
    bodies.push({
      id: `d${String(bodies.length - 1).padStart(6, "0")}`,
      x,
      y,
      r: 1,
      m: 1,
      vx: speed * Math.cos(a),
      vy: speed * Math.sin(a),
      mu: 0,
    });
  }
  if (bodies.length <= n) throw new Error(`bigDiscGas: room for only ${bodies.length - 1} of ${n} discs`);
  return {
    id: `big-disc-${bigR}`,
    title: `Brownian motion: a disc of radius ${bigR} among ${n} of radius 1`,
    description: `${n} discs r = 1, m = 1, speed ${speed} (seed ${seed}) around a disc r = ${bigR}, m = ${bigR * bigR} at rest, in a ${side.toFixed(2)} square box, 10 % packing; elastic, frictionless`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies,
    walls: boxWalls(0, 0, side, side, 10),
  };
}
