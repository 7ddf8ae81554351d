// pathLine: the Path view's polyline from the engine's exact pieces: ends of straight pieces, even
// samples of curved ones (exact positions), breaks where an action moved the body, and a cap that
// says where it cut.
import { positionAt, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { PathPiece } from "../engineTypes";
import { sceneOf } from "../testing/scenes";
import { CURVE_SEGMENTS, pathLine } from "./pathLine";

const piece = (p: Partial<PathPiece>): PathPiece => ({
  from: 0,
  until: 1,
  t0: 0,
  x0: 0,
  y0: 0,
  vx: 0,
  vy: 0,
  ax: 0,
  ay: 0,
  tStop: Number.POSITIVE_INFINITY,
  ...p,
});

/** The line's points as [x, y] pairs. */
const pairs = (a: Float64Array): [number, number][] =>
  Array.from({ length: a.length / 2 }, (_, k) => [a[2 * k] as number, a[2 * k + 1] as number]);

describe("pathLine", () => {
  it("straight pieces joined end to end give one point per joint", () => {
    const line = pathLine([piece({ vx: 2 }), piece({ from: 1, until: 3, t0: 1, x0: 2, vy: 1 })]);
    expect(pairs(line.points)).toEqual([
      [0, 0],
      [2, 0],
      [2, 2],
    ]);
    expect(line.cutAt).toBeNull();
  });

  it("a curved piece is sampled evenly in time up to its stop, at its exact positions", () => {
    const p = piece({ vx: 4, vy: 1, ax: -2, ay: -0.5, tStop: 2, until: 5 });
    const pts = pairs(pathLine([p]).points);
    expect(pts).toHaveLength(CURVE_SEGMENTS + 1);
    pts.forEach(([x, y], k) => {
      const t = (2 * k) / CURVE_SEGMENTS;
      expect(x).toBe(positionAt(0, 0, 4, -2, t));
      expect(y).toBe(positionAt(0, 0, 1, -0.5, t));
    });
    expect(pts[CURVE_SEGMENTS]).toEqual([4, 1]); // where it stops: 4·2 − 2·4/2, 1·2 − 0.5·4/2
  });

  it("a piece that starts elsewhere than the last one ended breaks the line (an action moved the body)", () => {
    const line = pathLine([piece({ vx: 1 }), piece({ from: 1, until: 2, t0: 1, x0: 50 })]);
    const pts = pairs(line.points);
    expect(pts.slice(0, 2)).toEqual([
      [0, 0],
      [1, 0],
    ]);
    expect(pts[2]?.every(Number.isNaN)).toBe(true);
    expect(pts.slice(3)).toEqual([
      [50, 0],
      [50, 0],
    ]);
  });

  it("a path longer than maxPoints is cut after the last whole piece that fits, and says where", () => {
    const pieces = Array.from({ length: 10 }, (_, k) =>
      piece({ from: k, until: k + 1, t0: k, x0: k, vx: 1 }),
    );
    const line = pathLine(pieces, 5);
    expect(pairs(line.points)).toEqual([
      [0, 0],
      [1, 0],
      [2, 0],
      [3, 0],
      [4, 0],
    ]);
    expect(line.cutAt).toBe(4);
    expect(pathLine(pieces, 11).cutAt).toBeNull();
  });

  it("a ball bouncing on a floor: a parabola per bounce, joined at each bounce", () => {
    const tl = Timeline.fromScene(
      {
        ...sceneOf([{ time: 0, type: "addBody", id: "b", x: 0, y: 10, r: 1, m: 1, v: [1, 0] }], 0),
        gravity: [0, -9.81],
      },
      { compute: false },
    );
    tl.apply({ time: 0, type: "addLine", id: "floor", p1: [-100, 0], p2: [100, 0], kind: "segment" });
    tl.prolongTo(6);
    const pieces = tl.path("b");
    expect(pieces.length).toBeGreaterThan(2);
    const pts = pairs(pathLine(pieces).points);
    expect(pts).toHaveLength(pieces.length * CURVE_SEGMENTS + 1);
    expect(pts.some(([x]) => Number.isNaN(x))).toBe(false);
    expect(Math.min(...pts.map(([, y]) => y))).toBeCloseTo(1, 9); // the disc's centre never below r
  });
});
