/**
 * Gas of N equal discs (r = 1, m = 1, speed `speed` in seeded random directions) on a grid in a
 * square box sized for the packing fraction N·π·r²/L²; elastic, frictionless, no gravity.
 * Used for the dilute (10 %) and dense (40 %) peer scenes and the engine's scaling runs.
 */
import { lcg } from "../lib/lcg.mjs";
import { boxWalls } from "./walls.mjs";

export function gas({ n = 1000, packing = 0.1, speed = 10, seed = 1, span = 10, r = 1 } = {}) {
  const side = Math.sqrt((n * Math.PI * r * r) / packing);
  const k = Math.ceil(Math.sqrt(n));
  const cell = side / k;
  if (cell <= 2 * r) throw new Error(`gas: packing ${packing} too dense for a grid start`);
  const rnd = lcg(seed);
  const bodies = [];
  for (let i = 0; i < n; i++) {
    const a = 2 * Math.PI * rnd();
    bodies.push({
      id: `b${String(i).padStart(6, "0")}`,
      x: ((i % k) + 0.5) * cell,
      y: (Math.floor(i / k) + 0.5) * cell,
      r,
      m: 1,
      vx: speed * Math.cos(a),
      vy: speed * Math.sin(a),
      mu: 0,
    });
  }
  return {
    id: packing >= 0.3 ? "dense-gas" : "dilute-gas",
    title: `${packing >= 0.3 ? "Dense" : "Dilute"} gas: ${n} discs, ${Math.round(packing * 100)} % packing`,
    description: `${n} discs r = ${r}, m = 1, speed ${speed} in seeded random directions (seed ${seed}), grid start in a ${side.toFixed(2)} × ${side.toFixed(2)} box; elastic, frictionless, no gravity; simulate ${span} s.`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies,
    walls: boxWalls(0, 0, side, side, 10),
    box: { x0: 0, y0: 0, x1: side, y1: side },
    elastic: true,
    exact: null,
  };
}
