// The crush in line alone (lineCrush.ts): a disc on an axis-parallel line between a still end across
// it and an immovable disc P coming along it; proven only when everything is symmetric about the
// line to the bit, and P closes on the disc before its motion ends.
import { describe, expect, it } from "vitest";
import { ZENO_TRAP_GAP } from "../tolerances.js";
import { type LineDisc, lineCloses } from "./lineCrush.js";
import type { Core } from "./pocketGeometry.js";

const INF = Number.POSITIVE_INFINITY;
const wall: Core = { kind: "line", x1: 0, y1: -10, x2: 0, y2: 10, rad: 0 };
const gap = 0.5 * ZENO_TRAP_GAP;

/** A motion record (t0, x0, y0, vx, vy, ax, ay, tEnd) starting at t = 0. */
function motion(x: number, y: number, vx: number, vy: number, ax = 0, ay = 0, tEnd = INF): number[] {
  return [0, x, y, vx, vy, ax, ay, tEnd];
}

/** The disc (r 1) at (1.5, y) moving along x, P (R 1) `gap` short of closing on it against `end`. */
function along(
  opts: { y?: number; vy?: number; pY?: number; pVy?: number; end?: Core; decel?: number } = {},
) {
  const d: LineDisc = { x: 1.5, y: opts.y ?? 0, vx: 3, vy: opts.vy ?? 0, ax: 0, ay: 0, r: 1 };
  const decel = opts.decel ?? 0;
  const mot = motion(3 + gap, opts.pY ?? 0, -1, opts.pVy ?? 0, decel, 0, decel > 0 ? 1 / decel : INF);
  const hull = new Float64Array(6);
  const corridor = new Float64Array(4);
  const t = lineCloses(0, d, mot, 0, 1, opts.end ?? wall, hull, corridor);
  return { t, hull, corridor };
}

describe("a disc in line between a wall and P", () => {
  it("is proven crushed by the time P comes within 2 r of the wall", () => {
    const { t, hull, corridor } = along();
    expect(t).toBeGreaterThan(gap);
    expect(t).toBeLessThan(gap + 1e-4);
    expect([...hull]).toEqual([3 + gap, 0, 3 + gap - t / 2, 0, 3 + gap - t, 0]);
    // From the wall's foot to P's farthest point: where it is now.
    expect([...corridor]).toEqual([0, 0, 3 + gap, 0]);
  });

  it("not when anything is off the line by one ulp: then no symmetry keeps the disc on it", () => {
    const ulp = 2 ** -1074;
    expect(along({ y: ulp }).t).toBeNaN();
    expect(along({ vy: ulp }).t).toBeNaN();
    expect(along({ pY: ulp }).t).toBeNaN();
    expect(along({ pVy: ulp }).t).toBeNaN();
  });

  it("not when the end is not across the line, or its solid part misses it", () => {
    expect(along({ end: { kind: "line", x1: 0, y1: -10, x2: 1e-9, y2: 10, rad: 0 } }).t).toBeNaN();
    expect(along({ end: { kind: "segment", x1: 0, y1: 1, x2: 0, y2: 10, rad: 0 } }).t).toBeNaN();
    expect(along({ end: { kind: "ray", x1: 0, y1: 1, x2: 0, y2: 10, rad: 0 } }).t).toBeNaN();
    expect(along({ end: { kind: "ray", x1: 0, y1: -1, x2: 0, y2: 10, rad: 0 } }).t).toBeGreaterThan(0);
  });

  it("a point or an immovable disc at rest on the line is an end too", () => {
    expect(along({ end: { kind: "point", x1: 0, y1: 0, x2: 0, y2: 0, rad: 0 } }).t).toBeGreaterThan(0);
    // A disc of radius 0.5 centred at x = -0.5: its surface where the wall was.
    expect(along({ end: { kind: "point", x1: -0.5, y1: 0, x2: -0.5, y2: 0, rad: 0.5 } }).t).toBeGreaterThan(
      0,
    );
    expect(along({ end: { kind: "point", x1: 0, y1: 1e-9, x2: 0, y2: 1e-9, rad: 0 } }).t).toBeNaN();
  });

  it("not when friction stops P short, nor before it is within ZENO_TRAP_GAP r", () => {
    expect(along({ decel: 1 / (2 * (gap - 1e-6)) }).t).toBeNaN();
    const far = lineCloses(
      0,
      { x: 1.5, y: 0, vx: 3, vy: 0, ax: 0, ay: 0, r: 1 },
      motion(3 + 2 * ZENO_TRAP_GAP, 0, -1, 0),
      0,
      1,
      wall,
      new Float64Array(6),
      new Float64Array(4),
    );
    expect(far).toBeNaN();
  });

  it("along y too: a ball on a floor under gravity, P falling on it from straight above", () => {
    const floor: Core = { kind: "segment", x1: -10, y1: 0, x2: 10, y2: 0, rad: 0 };
    const d: LineDisc = { x: 0, y: 1.2, vx: 0, vy: 2, ax: 0, ay: -9.81, r: 1 };
    const t = lineCloses(
      0,
      d,
      motion(0, 3 + gap, 0, -1, 0, -9.81),
      0,
      1,
      floor,
      new Float64Array(6),
      new Float64Array(4),
    );
    expect(t).toBeGreaterThan(gap);
    expect(t).toBeLessThan(gap + 1e-4);
    // With a sideways acceleration (a field not along the line) the disc leaves the line.
    const tilted = { ...d, ax: 1e-3 };
    expect(
      lineCloses(
        0,
        tilted,
        motion(0, 3 + gap, 0, -1, 0, -9.81),
        0,
        1,
        floor,
        new Float64Array(6),
        new Float64Array(4),
      ),
    ).toBeNaN();
  });
});
