/**
 * Numerical stress scenes, shared by the benchmark (bench/stress/run.mjs, large sizes) and the fast
 * invariant tests (tests/stress/*.test.ts, small sizes). Each returns an engine-neutral scene (the
 * format of bench/scenes: { id, span, g, gravity, bodies, walls, box }) plus `tolerance`, the
 * overlap (relative to the contact distance) the scene can honestly promise: 1e-9, or more where
 * positions are so large that one ulp of a coordinate is a bigger fraction of a radius.
 */
import { lcg } from "../lib/lcg.mjs";
import { boxWalls } from "../scenes/walls.mjs";

const id = (k) => `s${String(k).padStart(5, "0")}`;

/** A scene without gravity or friction field: open (no walls) unless `box` parts are given. */
function scene(sceneId, span, bodies, { walls = [], box = null } = {}, tolerance = 1e-9) {
  return { id: sceneId, span, g: 0, gravity: [0, 0], bodies, walls, box, tolerance };
}

/**
 * A box gas: n discs of radius r on a grid start at `packing` in a square box whose lower-left
 * corner is (o, o), directions from a seeded generator; `disc(i)` gives each disc's mass and speed.
 */
function boxGas({ n, r = 1, packing, o = 0, seed, wall = 1, disc }) {
  const side = Math.sqrt((n * Math.PI * r * r) / packing);
  const k = Math.ceil(Math.sqrt(n));
  const cell = side / k;
  const rnd = lcg(seed);
  const bodies = [];
  for (let i = 0; i < n; i++) {
    const a = 2 * Math.PI * rnd();
    const { m, speed } = disc(i);
    bodies.push({
      id: id(i),
      x: o + ((i % k) + 0.5) * cell,
      y: o + (Math.floor(i / k) + 0.5) * cell,
      r,
      m,
      vx: speed * Math.cos(a),
      vy: speed * Math.sin(a),
      mu: 0,
    });
  }
  return {
    bodies,
    walls: boxWalls(o, o, o + side, o + side, wall),
    box: { x0: o, y0: o, x1: o + side, y1: o + side },
  };
}

/**
 * Grazing collisions: `lanes` independent pairs, each a disc moving at speed 1 past a resting one
 * with impact parameter (1 − δ)·R, δ = 10^-(lane mod 17) (δ = 1e-16 is a tangent pass), lanes 10 apart.
 */
export function grazing(lanes = 17) {
  const bodies = [];
  for (let k = 0; k < lanes; k++) {
    const delta = 10 ** -(k % 17);
    const y = 10 * k;
    bodies.push({ id: id(2 * k), x: 0, y, r: 1, m: 1, vx: 0, vy: 0, mu: 0 });
    bodies.push({ id: id(2 * k + 1), x: -4, y: y + 2 * (1 - delta), r: 1, m: 1, vx: 1, vy: 0, mu: 0 });
  }
  return scene("grazing", 10, bodies);
}

/**
 * Near-simultaneous events: a striker moving along +x meets two discs placed symmetrically above
 * and below its path, one shifted by ε = 10^-k along x (k = 8…16 and ε = 0), one lane per ε.
 */
export function nearSimultaneous(lanes = 10) {
  const bodies = [];
  for (let k = 0; k < lanes; k++) {
    const eps = k === 0 ? 0 : 10 ** -(7 + k);
    const y = 12 * k;
    bodies.push({ id: id(3 * k), x: -5, y, r: 1, m: 1, vx: 2, vy: 0, mu: 0 });
    bodies.push({ id: id(3 * k + 1), x: 0, y: y + 1.2, r: 1, m: 1, vx: 0, vy: 0, mu: 0 });
    bodies.push({ id: id(3 * k + 2), x: eps, y: y - 1.2, r: 1, m: 1, vx: 0, vy: 0, mu: 0 });
  }
  return scene("near-simultaneous", 10, bodies);
}

/**
 * Contacts at t ≈ 0 after round-off: rings of n discs touching their neighbours, centres computed
 * with cos/sin (distances 2r ± a few ulps, nudged so none overlaps), all moving inwards, so the
 * first collisions happen at t ≈ 0 between bodies whose gap is pure round-off.
 */
export function roundOffContacts(rings = 4, n = 24) {
  const bodies = [];
  let k = 0;
  for (let ring = 0; ring < rings; ring++) {
    const r = 1;
    const cx = ring * 4 * (r / Math.sin(Math.PI / n));
    const place = (rho) =>
      Array.from({ length: n }, (_, i) => {
        const a = (2 * Math.PI * i) / n + ring * 0.1;
        return {
          x: cx + rho * Math.cos(a),
          y: rho * Math.sin(a),
          vx: -Math.cos(a),
          vy: -Math.sin(a),
          m: 1 + (i % 3),
        };
      });
    const touching = (list) =>
      list.every((p, i) => {
        const q = list[(i + 1) % n];
        return (q.x - p.x) ** 2 + (q.y - p.y) ** 2 >= 4 * r * r;
      });
    // the exact touching radius, grown by ulps until no neighbour pair overlaps in doubles
    let rho = r / Math.sin(Math.PI / n);
    let list = place(rho);
    for (let i = 0; i < 200 && !touching(list); i++) {
      rho *= 1 + 2 ** -52;
      list = place(rho);
    }
    for (const p of list) bodies.push({ id: id(k++), r, mu: 0, ...p });
  }
  return scene("round-off-contacts", 30, bodies);
}

/** A gas of `n` discs (r = 1e-3) whose box sits at (1e6, 1e6): one ulp of a coordinate is 1.2e-10. */
export function largeOffset(n = 200, seed = 3) {
  const r = 1e-3;
  const gas = boxGas({ n, r, packing: 0.1, o: 1e6, seed, disc: () => ({ m: 1, speed: 0.01 }) });
  // one ulp at 1e6 relative to the contact distance 2r, times a small factor for the contact geometry
  const ulp = 2 ** -33;
  return scene("large-offset", 20, gas.bodies, gas, Math.max(1e-9, (8 * ulp) / (2 * r)));
}

/** A box gas of `n` discs with one disc `ratio` times heavier than the rest. */
export function massRatio(ratio, n = 40, seed = 4) {
  const disc = (i) => (i === 0 ? { m: ratio, speed: 0.1 } : { m: 1, speed: 3 });
  const gas = boxGas({ n, packing: 0.15, seed, disc });
  return scene(`mass-ratio-${ratio}`, 20, gas.bodies, gas);
}

/** A box gas of `n` discs at speed 1 with `fast` of them at speed `speed`. */
export function highSpeed(speed, n = 60, fast = 2, seed = 5) {
  const gas = boxGas({ n, packing: 0.1, seed, disc: (i) => ({ m: 1, speed: i < fast ? speed : 1 }) });
  return scene(`high-speed-${speed}`, 20 / Math.sqrt(speed), gas.bodies, gas);
}
