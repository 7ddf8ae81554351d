/**
 * A 10 % gas of `n` discs whose radii come from `radius(i, rnd)` (mass r², speed `speed` in seeded
 * random directions, elastic, frictionless) in a square box: the mixed-radii rows with many large
 * discs and with radii spread over a range. Discs are placed largest first at seeded random spots
 * that overlap nothing (with a 0.01 gap), found with a coarse hash of the placed discs.
 */
import { lcg } from "../lib/lcg.mjs";
import { boxWalls } from "./walls.mjs";

/** The radius laws the benchmark uses, by name. */
export const RADIUS_LAWS = {
  "100 discs r = 5": (i) => (i < 100 ? 5 : 1),
  "100 discs r = 20": (i) => (i < 100 ? 20 : 1),
  "20 discs r = 10": (i) => (i < 20 ? 10 : 1),
  "r log-uniform 1 to 30": (_i, rnd) => Math.exp(rnd() * Math.log(30)),
};

export function polydisperseGas({ n = 10000, law, packing = 0.1, speed = 10, seed = 5, span = 1e9 }) {
  const radius = RADIUS_LAWS[law];
  if (!radius) throw new Error(`polydisperseGas: unknown radius law '${law}'`);
  const rnd = lcg(seed);
  const radii = Array.from({ length: n }, (_, i) => radius(i, rnd));
  const side = Math.sqrt(radii.reduce((a, r) => a + Math.PI * r * r, 0) / packing);
  const cs = 2 * Math.max(...radii) + 0.01;
  const cells = new Map();
  const bodies = [];
  const order = radii.map((r, i) => [r, i]).sort((a, b) => b[0] - a[0] || a[1] - b[1]);
  for (const [r, i] of order) {
    for (let tries = 0; ; tries++) {
      if (tries > 100000) throw new Error(`polydisperseGas: no room for disc ${i} (r = ${r})`);
      const x = r + 0.01 + rnd() * (side - 2 * r - 0.02);
      const y = r + 0.01 + rnd() * (side - 2 * r - 0.02);
      const cx = Math.floor(x / cs);
      const cy = Math.floor(y / cs);
      let free = true;
      for (let a = cx - 1; a <= cx + 1 && free; a++)
        for (let b = cy - 1; b <= cy + 1 && free; b++)
          for (const o of cells.get(`${a},${b}`) ?? []) {
            const R = o.r + r + 0.01;
            if ((o.x - x) ** 2 + (o.y - y) ** 2 < R * R) {
              free = false;
              break;
            }
          }
      if (!free) continue;
      const a = 2 * Math.PI * rnd();
      const body = {
        id: `d${String(i).padStart(6, "0")}`,
        x,
        y,
        r,
        m: r * r,
        vx: speed * Math.cos(a),
        vy: speed * Math.sin(a),
        mu: 0,
      };
      bodies.push(body);
      const key = `${cx},${cy}`;
      if (!cells.has(key)) cells.set(key, []);
      cells.get(key).push(body);
      break;
    }
  }
  return {
    id: `polydisperse-${law.replace(/[^a-z0-9]+/gi, "-")}`,
    title: `10 % gas of ${n} discs, ${law}, the others r = 1`,
    description: `${n} discs (${law}${law.startsWith("r ") ? "" : ", the others r = 1"}), m = r², speed ${speed} (seed ${seed}), in a ${side.toFixed(2)} square box, 10 % packing; elastic, frictionless`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies,
    walls: boxWalls(0, 0, side, side, 10),
  };
}
