// The crush in line alone (lineCrush.ts): a disc, or a row of discs, on an axis-parallel line
// between a still end across it and an immovable disc P coming along it; proven only when everything
// is symmetric about the line to the bit, and P closes on the row before its motion ends.
import { describe, expect, it } from "vitest";
import { ZENO_TRAP_GAP, ZENO_TRAP_SLACK } from "../tolerances.js";
import { footOf, type LineDisc, lineAxis, lineCloses, orderedSum } from "./lineCrush.js";
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

/** A disc of radius r at rest at (x, y), or moving with (vx, vy). */
function disc(x: number, y: number, r = 1, vx = 0, vy = 0): LineDisc {
  return { x, y, vx, vy, ax: 0, ay: 0, r };
}

describe("a row of discs in line between a wall and P", () => {
  /**
   * A row against the wall: the disc d (r 1) struck by P (radius R) coming along x at speed 1,
   * `short` short of closing on d and discs of radii `radii` (between d and the wall, moving);
   * `others` are passed as well.
   */
  function row(short: number, radii: readonly number[], others: readonly LineDisc[] = [], R = 1) {
    const length = 2 * (1 + radii.reduce((a, b) => a + b, 0));
    const d = disc(length - 1.1, 0, 1, 2);
    const all = [
      ...radii.map((r, i) => disc((d.x * (i + 1)) / (radii.length + 1), 0, r, i % 2 ? 1 : -1)),
      ...others,
    ];
    const mot = motion(R + length + short, 0, -1, 0);
    const inRow: boolean[] = [];
    const corridor = new Float64Array(4);
    const t = lineCloses(0, d, mot, 0, R, wall, new Float64Array(6), corridor, all, inRow);
    return { t, inRow, corridor, length };
  }

  /** The latest t* can be: when P reaches the row's length with each radius 3 slacks less. */
  const latest = (short: number, length: number): number =>
    (short + 3 * length * ZENO_TRAP_SLACK) * (1 + 1e-9);

  it("is proven crushed by the time P comes within the row's length of the wall", () => {
    const { t, inRow, corridor, length } = row(gap, [1, 1]);
    expect(t).toBeGreaterThan(gap);
    expect(t).toBeLessThanOrEqual(latest(gap, length));
    expect(inRow).toEqual([true, true]);
    expect([...corridor]).toEqual([0, 0, 7 + gap, 0]);
  });

  it("not before P is within ZENO_TRAP_GAP r of closing on the whole row (one disc fewer fits easily)", () => {
    expect(row(2 * ZENO_TRAP_GAP, [1, 1]).t).toBeNaN();
    // The same P with one disc of the row missing is 2 r from closing: no proof.
    expect(row(gap + 2, [1]).t).toBeNaN();
    // Closed already (only round-off could have put the row there): no proof.
    expect(row(-gap, [1, 1]).t).toBeNaN();
  });

  it("the discs of the row may have any radii; the smallest sets the gap at which it is tried", () => {
    const near = 0.1 * ZENO_TRAP_GAP;
    expect(row(near, [0.5, 0.25]).t).toBeGreaterThan(near);
    expect(row(near, [0.5, 0.25]).t).toBeLessThanOrEqual(latest(near, 3.5));
    // 0.5 ZENO_TRAP_GAP (the gap) is more than ZENO_TRAP_GAP × 0.25: not yet.
    expect(row(gap, [1, 1]).t).toBeGreaterThan(0);
    expect(row(gap, [1, 0.25]).t).toBeNaN();
  });

  it("only the discs centred on the line and keeping to it, between the wall and P, are in the row", () => {
    const ulp = 2 ** -1074;
    const others = [
      disc(20, 0), // behind P
      disc(-3, 0), // behind the wall
      disc(3.5, ulp), // off the line by one ulp
      disc(3.5, 0, 1, 1, ulp), // leaving it
      { ...disc(3.5, 0), ay: ulp }, // pulled off it
    ];
    const { t, inRow } = row(gap, [1], others);
    expect(t).toBeGreaterThan(0);
    expect(inRow).toEqual([true, false, false, false, false, false]);
  });

  it("along y: a stack of balls on a floor under gravity, P falling on it from straight above", () => {
    const floor: Core = { kind: "segment", x1: -10, y1: 0, x2: 10, y2: 0, rad: 0 };
    const d: LineDisc = { x: 0, y: 3.2, vx: 0, vy: 2, ax: 0, ay: -9.81, r: 1 };
    const below: LineDisc = { x: 0, y: 1.1, vx: 0, vy: -1, ax: 0, ay: -9.81, r: 1 };
    const mot = motion(0, 5 + gap, 0, -1, 0, -9.81);
    const inRow: boolean[] = [];
    const t = lineCloses(0, d, mot, 0, 1, floor, new Float64Array(6), new Float64Array(4), [below], inRow);
    // Faster than 1 under gravity: sooner than at speed 1.
    expect(t).toBeGreaterThan(gap / 2);
    expect(t).toBeLessThanOrEqual(latest(gap, 4));
    expect(inRow).toEqual([true]);
  });
});

describe("the line and its ends", () => {
  it("a disc at rest takes P's line; a moving disc its own", () => {
    expect(lineAxis(disc(0, 0), motion(5, 0, -1, 0), 0)).toBe(0);
    expect(lineAxis(disc(0, 0), motion(0, 5, 0, -1), 0)).toBe(1);
    expect(lineAxis(disc(0, 0, 1, 1, 0), motion(0, 5, 0, -1), 0)).toBe(-1);
    expect(lineAxis(disc(0, 0, 1, 0, 1), motion(0, 5, 0, -1), 0)).toBe(1);
    // P beside the line: not on it.
    expect(lineAxis(disc(0, 0, 1, 1, 0), motion(5, 1e-9, -1, 0), 0)).toBe(-1);
  });

  it("the foot: where the line meets a point on it or a line across it", () => {
    expect(footOf(wall, 0, 3)).toBe(0);
    expect(footOf({ kind: "segment", x1: 2, y1: -1, x2: 2, y2: 1, rad: 0 }, 0, 1)).toBe(2);
    expect(footOf({ kind: "segment", x1: 2, y1: -1, x2: 2, y2: 1, rad: 0 }, 0, 1.5)).toBeNaN();
    expect(footOf({ kind: "point", x1: 4, y1: 7, x2: 4, y2: 7, rad: 0.5 }, 1, 4)).toBe(7);
    expect(footOf({ kind: "point", x1: 4, y1: 7, x2: 4, y2: 7, rad: 0.5 }, 0, 4)).toBeNaN();
    // A line along the line itself is no end.
    expect(footOf({ kind: "line", x1: 0, y1: 0, x2: 1, y2: 0, rad: 0 }, 0, 0)).toBeNaN();
  });
});

describe("orderedSum", () => {
  it("gives the same bits whatever order the numbers come in", () => {
    const values = [1e16, 1, -1e16, 0.1, 3, 2 ** -30, 7.5];
    const sum = orderedSum([...values]);
    expect(orderedSum([...values].reverse())).toBe(sum);
    expect(
      orderedSum([values[3], values[0], values[6], values[1], values[5], values[2], values[4]] as number[]),
    ).toBe(sum);
    // Left to right, as given, the order changes the bits.
    expect(values.reduce((a, b) => a + b, 0)).not.toBe([...values].reverse().reduce((a, b) => a + b, 0));
  });
});
