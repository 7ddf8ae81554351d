/**
 * Obstacle-heavy scenes: a few discs among many static segments or points, where the broad phase
 * must index the obstacles (not only the bodies) for an event to cost less than a test of every
 * obstacle. Engine-neutral like the other scenes, plus `points` ({ id, p }) for pegs.
 * - maze: `discs` discs (r = 1, speed 10) in a square lattice of corridors 6 wide, walled by
 *   `segments` unit-lattice segments in all (the outer boundary first, then interior walls chosen
 *   at random); elastic, frictionless, no gravity.
 * - galton: `balls` balls (r = 1) falling under gravity (0, −10) through a triangular lattice of
 *   `pegs` points 4 apart, in a box of 4 segments; elastic, frictionless.
 */
import { lcg } from "../lib/lcg.mjs";
import { boxWalls } from "./walls.mjs";

const CORRIDOR = 6;

/** Fisher–Yates shuffle with a seeded generator (in place). */
function shuffle(items, rnd) {
  for (let i = items.length - 1; i > 0; i--) {
    const j = Math.floor(rnd() * (i + 1));
    [items[i], items[j]] = [items[j], items[i]];
  }
  return items;
}

export function maze({ discs = 8, segments = 1000, seed = 1, span = 1e9 } = {}) {
  // k x k cells: 4k boundary walls and 2k(k - 1) interior ones; about half the interior ones kept.
  const k = Math.max(2, Math.round(Math.sqrt(segments)));
  const c = CORRIDOR;
  const rnd = lcg(seed);
  const wall = (id, x1, y1, x2, y2) => ({
    id,
    p1: [x1, y1],
    p2: [x2, y2],
    kind: "segment",
    inside: [0, 1],
    thickness: 1,
  });
  const outer = [];
  for (let i = 0; i < k; i++) {
    outer.push(wall(`wb${i}`, i * c, 0, (i + 1) * c, 0), wall(`wt${i}`, i * c, k * c, (i + 1) * c, k * c));
    outer.push(wall(`wl${i}`, 0, i * c, 0, (i + 1) * c), wall(`wr${i}`, k * c, i * c, k * c, (i + 1) * c));
  }
  const inner = [];
  for (let i = 1; i < k; i++)
    for (let j = 0; j < k; j++) {
      inner.push(wall(`v${i}_${j}`, i * c, j * c, i * c, (j + 1) * c));
      inner.push(wall(`h${j}_${i}`, j * c, i * c, (j + 1) * c, i * c));
    }
  shuffle(inner, rnd);
  const walls = [...outer, ...inner.slice(0, Math.max(0, segments - outer.length))];
  const cells = shuffle(
    Array.from({ length: k * k }, (_, i) => i),
    rnd,
  );
  const bodies = [];
  for (let i = 0; i < discs; i++) {
    const cell = cells[i % cells.length];
    const a = 2 * Math.PI * rnd();
    bodies.push({
      id: `d${String(i).padStart(3, "0")}`,
      x: ((cell % k) + 0.5) * c,
      y: (Math.floor(cell / k) + 0.5) * c,
      r: 1,
      m: 1,
      mu: 0,
      vx: 10 * Math.cos(a),
      vy: 10 * Math.sin(a),
    });
  }
  return {
    id: `maze-${discs}-${walls.length}`,
    title: `Maze: ${discs} discs, ${walls.length} segments`,
    description: `${discs} discs r = 1, speed 10 in seeded random directions (seed ${seed}), in a ${k} × ${k} lattice of cells ${c} wide walled by ${walls.length} segments (the boundary and random interior walls); elastic, frictionless, no gravity.`,
    span,
    g: 0,
    gravity: [0, 0],
    bodies,
    walls,
    points: [],
    box: { x0: 0, y0: 0, x1: k * c, y1: k * c },
    elastic: true,
    exact: null,
  };
}

export function galton({ balls = 5, pegs = 2000, seed = 1, span = 1e9 } = {}) {
  const gap = 4;
  const cols = Math.max(2, Math.round(Math.sqrt(pegs)));
  const rows = Math.ceil(pegs / cols);
  const width = (cols + 1) * gap;
  const height = (rows + 4) * gap;
  const points = [];
  for (let i = 0; i < pegs; i++) {
    const row = Math.floor(i / cols);
    const col = i % cols;
    points.push({
      id: `p${String(i).padStart(5, "0")}`,
      p: [(col + 0.75 + (row % 2) * 0.5) * gap, (row + 1) * gap],
    });
  }
  const rnd = lcg(seed);
  const bodies = [];
  for (let i = 0; i < balls; i++)
    bodies.push({
      id: `ball${i}`,
      x: width / 2 + (i - (balls - 1) / 2) * 2.5,
      y: height - 2,
      r: 1,
      m: 1,
      mu: 0,
      vx: 2 * rnd() - 1,
      vy: 0,
    });
  return {
    id: `galton-${balls}-${pegs}`,
    title: `Galton board: ${balls} balls, ${pegs} pegs`,
    description: `${balls} balls r = 1 falling under gravity (0, −10) through a triangular lattice of ${pegs} point pegs ${gap} apart (${rows} rows of ${cols}), in a ${width} × ${height} box of 4 segments; elastic, frictionless.`,
    span,
    g: 0,
    gravity: [0, -10],
    bodies,
    walls: boxWalls(0, 0, width, height, 1),
    points,
    box: { x0: 0, y0: 0, x1: width, y1: height },
    elastic: true,
    exact: null,
  };
}
