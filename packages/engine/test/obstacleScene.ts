/**
 * Test support: a seeded maze of many segments and pegs (points) with a few discs, as plain data,
 * and ways to build it into a World in a given order. The lattice has cells 6 wide; each disc
 * (r = 1, speed 10) starts at a cell's centre, each peg 1 in from a cell's corner, so nothing
 * overlaps whatever subset of walls is kept.
 */
import type { Vec2 } from "../src/sim/types.js";
import { World } from "../src/sim/world.js";
import { lcg } from "./randomScene.js";

export interface MazeWall {
  id: string;
  p1: Vec2;
  p2: Vec2;
}
export interface MazePeg {
  id: string;
  p: Vec2;
}
export interface MazeDisc {
  id: string;
  x: number;
  y: number;
  vx: number;
  vy: number;
}
export interface Maze {
  walls: MazeWall[];
  pegs: MazePeg[];
  discs: MazeDisc[];
}

export const CELL = 6;

/** A k x k maze: its boundary, about half the interior walls (at random), `pegs` pegs, `discs` discs. */
export function maze(seed: number, k: number, pegs: number, discs: number): Maze {
  const rnd = lcg(seed);
  const c = CELL;
  const walls: MazeWall[] = [];
  for (let i = 0; i < k; i++) {
    walls.push({ id: `b${i}`, p1: [i * c, 0], p2: [(i + 1) * c, 0] });
    walls.push({ id: `t${i}`, p1: [i * c, k * c], p2: [(i + 1) * c, k * c] });
    walls.push({ id: `l${i}`, p1: [0, i * c], p2: [0, (i + 1) * c] });
    walls.push({ id: `r${i}`, p1: [k * c, i * c], p2: [k * c, (i + 1) * c] });
  }
  for (let i = 1; i < k; i++)
    for (let j = 0; j < k; j++) {
      if (rnd() < 0.5) walls.push({ id: `v${i}_${j}`, p1: [i * c, j * c], p2: [i * c, (j + 1) * c] });
      if (rnd() < 0.5) walls.push({ id: `h${j}_${i}`, p1: [j * c, i * c], p2: [(j + 1) * c, i * c] });
    }
  const corners = [
    [1, 1],
    [c - 1, 1],
    [1, c - 1],
    [c - 1, c - 1],
  ] as const;
  const taken = new Set<string>();
  const pegList: MazePeg[] = [];
  for (let n = 0; n < pegs; n++) {
    const cell = Math.floor(rnd() * k * k);
    const [dx, dy] = corners[Math.floor(rnd() * 4)] as readonly [number, number];
    const p: Vec2 = [(cell % k) * c + dx, Math.floor(cell / k) * c + dy];
    if (taken.has(`${p}`)) continue;
    taken.add(`${p}`);
    pegList.push({ id: `p${String(n).padStart(5, "0")}`, p });
  }
  const discList: MazeDisc[] = [];
  const cells = new Set<number>();
  for (let n = 0; n < discs; n++) {
    const cell = Math.floor(rnd() * k * k);
    if (cells.has(cell)) continue;
    cells.add(cell);
    const a = 2 * Math.PI * rnd();
    discList.push({
      id: `d${n}`,
      x: ((cell % k) + 0.5) * c,
      y: (Math.floor(cell / k) + 0.5) * c,
      vx: 10 * Math.cos(a),
      vy: 10 * Math.sin(a),
    });
  }
  return { walls, pegs: pegList, discs: discList };
}

/** One add of a maze's wall (a line), peg (a point) or disc (a body), to make in a World. */
export interface MazeAdd {
  kind: "line" | "point" | "body";
  id: string;
  add(w: World): void;
}

/** The maze's adds: walls, then pegs, then discs (the order a scene file usually has). */
export function mazeAdds(m: Maze): MazeAdd[] {
  return [
    ...m.walls.map(
      (l): MazeAdd => ({ kind: "line", id: l.id, add: (w) => w.addLine(l.id, l.p1, l.p2, "segment") }),
    ),
    ...m.pegs.map((p): MazeAdd => ({ kind: "point", id: p.id, add: (w) => w.addPoint(p.id, p.p) })),
    ...m.discs.map(
      (d): MazeAdd => ({
        kind: "body",
        id: d.id,
        add: (w) => w.addBody(d.id, { x: d.x, y: d.y, r: 1, m: 1, vx: d.vx, vy: d.vy }),
      }),
    ),
  ];
}

/** A World with no friction or gravity, the adds made in the order given. */
export function mazeWorld(adds: readonly MazeAdd[]): World {
  const w = new World({ g: 0 });
  for (const a of adds) a.add(w);
  return w;
}

/** A seeded Fisher–Yates shuffle (a copy). */
export function shuffled<T>(items: readonly T[], seed: number): T[] {
  const rnd = lcg(seed);
  const out = items.slice();
  for (let i = out.length - 1; i > 0; i--) {
    const j = Math.floor(rnd() * (i + 1));
    [out[i], out[j]] = [out[j] as T, out[i] as T];
  }
  return out;
}

/** The World's lines or points in its internal order (the order the grid is laid out from). */
export function obstacleOrder(w: World): { lines: string[]; points: string[] } {
  // The lists are compacted by every public read (lines() does it).
  w.lines();
  const inner = w as unknown as { lineList: { id: string }[]; pointList: { id: string }[] };
  return { lines: inner.lineList.map((l) => l.id), points: inner.pointList.map((p) => p.id) };
}
