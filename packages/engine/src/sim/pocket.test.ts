// The closing-pocket proof alone (pocket.ts): a disc in a corner of a floor and a wall, between two
// discs, or in a dead end, with an immovable disc P closing on it; and the near misses it must not
// prove.
import { describe, expect, it } from "vitest";
import { ZENO_TRAP_GAP, ZENO_TRAP_SCALE } from "../tolerances.js";
import { pocketCloses } from "./pocket.js";
import type { Core } from "./pocketGeometry.js";

const C = Math.SQRT1_2;
const floor: Core = { kind: "segment", x1: 0, y1: 0, x2: 10, y2: 0, rad: 0 };
const wall: Core = { kind: "segment", x1: 0, y1: 0, x2: 0, y2: 10, rad: 0 };

/** A motion record (t0, x0, y0, vx, vy, ax, ay, tEnd) starting at t = 0. */
function motion(
  x: number,
  y: number,
  vx: number,
  vy: number,
  ax = 0,
  ay = 0,
  tEnd = Number.POSITIVE_INFINITY,
) {
  return [0, x, y, vx, vy, ax, ay, tEnd];
}

/**
 * The corner of `floor` and `wall`, shifted by (s, s): the disc (r 1) just off its corner spot
 * (1, 1), P (R 1) on the diagonal `gap` short of closing the pocket (its centre 2 + gap from the
 * spot), moving along `dir` at speed 1 (towards the spot by default) with the given deceleration.
 */
function corner(gap: number, opts: { shift?: number; dir?: [number, number]; decel?: number } = {}) {
  const s = opts.shift ?? 0;
  const [ux, uy] = opts.dir ?? [-C, -C];
  const decel = opts.decel ?? 0;
  const shifted = (k: Core): Core => ({ ...k, x1: k.x1 + s, y1: k.y1 + s, x2: k.x2 + s, y2: k.y2 + s });
  const p = 1 + s + (2 + gap) * C;
  const mot = motion(
    p,
    p,
    ux,
    uy,
    -decel * ux,
    -decel * uy,
    decel > 0 ? 1 / decel : Number.POSITIVE_INFINITY,
  );
  const hull = new Float64Array(6);
  const t = pocketCloses(
    0,
    1 + s + 1e-5,
    1 + s + 2e-5,
    1,
    mot,
    0,
    1,
    [shifted(floor), shifted(wall)],
    hull,
    0,
  );
  return { t, hull };
}

describe("a disc in a corner, an immovable disc closing on it", () => {
  it("is proven crushed once P is within ZENO_TRAP_GAP r of closing it, by the time it closes", () => {
    const gap = 0.5 * ZENO_TRAP_GAP;
    const { t, hull } = corner(gap);
    // P's centre reaches 2 (1 - 3 ZENO_TRAP_SLACK) from the spot a little after `gap` at speed 1.
    expect(t).toBeGreaterThan(gap);
    expect(t).toBeLessThan(gap + 1e-4);
    const p = 1 + (2 + gap) * C;
    expect([...hull.slice(0, 2)]).toEqual([p, p]);
    expect(hull[4]).toBeCloseTo(p - t * C, 15);
  });

  it("not while P is further than ZENO_TRAP_GAP r from closing it (not yet: no proof)", () => {
    expect(corner(2 * ZENO_TRAP_GAP).t).toBeNaN();
  });

  it("not when friction stops P short of closing it, however little short", () => {
    // Speed 1, deceleration 1 / (2 (gap - stop)): P stops `stop` short of the spot's 2 + 0.
    for (const stop of [1e-4, 1e-6, 1e-9]) {
      const gap = 0.5 * ZENO_TRAP_GAP;
      expect(corner(gap, { decel: 1 / (2 * (gap - stop)) }).t).toBeNaN();
    }
    // ... but when it stops past the closing, it is proven.
    expect(corner(0.5 * ZENO_TRAP_GAP, { decel: 1 / (2 * 0.6 * ZENO_TRAP_GAP) }).t).toBeGreaterThan(0);
  });

  it("not when P passes by without closing it", () => {
    // Moving across the diagonal: its nearest approach to the spot is 2 + gap.
    expect(corner(0.5 * ZENO_TRAP_GAP, { dir: [C, -C] }).t).toBeNaN();
    // Moving away.
    expect(corner(0.5 * ZENO_TRAP_GAP, { dir: [C, C] }).t).toBeNaN();
  });

  it("only where round-off is far below its margins (coordinates up to ZENO_TRAP_SCALE radii)", () => {
    expect(corner(0.5 * ZENO_TRAP_GAP, { shift: 0.25 * ZENO_TRAP_SCALE }).t).toBeGreaterThan(0);
    expect(corner(0.5 * ZENO_TRAP_GAP, { shift: 2 * ZENO_TRAP_SCALE }).t).toBeNaN();
  });

  it("not for a disc outside the pocket", () => {
    const p = 1 + (2 + 0.5 * ZENO_TRAP_GAP) * C;
    const mot = motion(p, p, -C, -C);
    // Beside P, against the floor.
    expect(pocketCloses(0, p + 2.5, 1, 1, mot, 0, 1, [floor, wall], new Float64Array(6), 0)).toBeNaN();
  });
});

describe("near misses that are no pocket", () => {
  it("a disc between P and a floor of two segments meeting at a joint: never a pocket", () => {
    // P descends onto the disc, which lies on the floor near the joint at 0: the floor's two parts
    // and P's disc meet all three where P meets either part, so no pocket ever encloses the disc.
    const left: Core = { kind: "segment", x1: -10, y1: 0, x2: 0, y2: 0, rad: 0 };
    const right: Core = { kind: "segment", x1: 0, y1: 0, x2: 10, y2: 0, rad: 0 };
    for (const px of [0, 0.3, 0.5, 1, 1.7])
      for (const dx of [-0.4, -0.1, 0, 0.2, 0.9])
        for (const gap of [1e-3, 1e-5, 1e-8]) {
          // The disc (r 1) on the floor at x = px + dx, P (R 1) coming down right onto it.
          const cx = px + dx;
          const cy = 1 + 1e-9;
          const py = cy + Math.sqrt(Math.max(0, (2 + gap) ** 2 - dx * dx));
          const mot = motion(px, py, 0, -1);
          expect(pocketCloses(0, cx, cy, 1, mot, 0, 1, [left, right], new Float64Array(6), 0)).toBeNaN();
        }
  });

  it("a disc in a channel exactly 2r + eps wide, P coming along it: the walls' sets never meet", () => {
    for (const eps of [0, 1e-12, 1e-6]) {
      const lower: Core = { kind: "line", x1: 0, y1: 0, x2: 1, y2: 0, rad: 0 };
      const upper: Core = { kind: "line", x1: 0, y1: 2 + eps, x2: 1, y2: 2 + eps, rad: 0 };
      const y = 1 + eps / 2;
      const mot = motion(7 + 1e-6, y, -1, 0);
      expect(pocketCloses(0, 5, y, 1, mot, 0, 1, [lower, upper], new Float64Array(6), 0)).toBeNaN();
    }
  });
});

describe("a disc between two immovable discs at rest, P coming down between them", () => {
  it("is proven crushed when P closes the pocket above it", () => {
    // Discs of radius 1 at (±1.2, 0); the disc (r 0.5) wedged at (0, 0.9); P (R 1) coming down.
    const left: Core = { kind: "point", x1: -1.2, y1: 0, x2: -1.2, y2: 0, rad: 1 };
    const right: Core = { kind: "point", x1: 1.2, y1: 0, x2: 1.2, y2: 0, rad: 1 };
    const gap = 0.5 * ZENO_TRAP_GAP * 0.5;
    const mot = motion(0, 0.9 + 1.5 + gap, 0, -1);
    const t = pocketCloses(0, 0, 0.9 + 1e-6, 0.5, mot, 0, 1, [left, right], new Float64Array(6), 0);
    expect(t).toBeGreaterThan(gap);
    expect(t).toBeLessThan(gap + 1e-4);
  });
});

describe("a disc in a dead-end channel, P coming in: a chain of three sides", () => {
  // Walls y = 0 and y = 2.001 (room 1e-3 for a disc of r 1), the end x = 0; the disc against the
  // end, P (R 1) along the channel's middle 1e-4 short of it.
  const lower: Core = { kind: "segment", x1: 0, y1: 0, x2: 50, y2: 0, rad: 0 };
  const upper: Core = { kind: "segment", x1: 0, y1: 2.001, x2: 50, y2: 2.001, rad: 0 };
  const end: Core = { kind: "segment", x1: 0, y1: 0, x2: 0, y2: 2.001, rad: 0 };
  const y = 1.0005;

  it("is proven crushed once P covers both corners of the end", () => {
    const mot = motion(3 + 1e-4, y, -1, 0);
    const t = pocketCloses(0, 1 + 1e-6, y, 1, mot, 0, 1, [lower, end, upper], new Float64Array(6), 0);
    // The corners' points (1, 1), (1, 1.001) are 2 from P's centre at x ≈ 3: t ≈ 1e-4.
    expect(t).toBeGreaterThan(1e-4 - 1e-6);
    expect(t).toBeLessThan(1e-4 + 1e-4);
  });

  it("not by two of its sides alone (the disc is not in a corner of the end)", () => {
    const mot = motion(3 + 1e-4, y, -1, 0);
    for (const pair of [
      [lower, end],
      [end, upper],
      [lower, upper],
    ])
      expect(pocketCloses(0, 1 + 1e-6, y, 1, mot, 0, 1, pair, new Float64Array(6), 0)).toBeNaN();
  });
});
