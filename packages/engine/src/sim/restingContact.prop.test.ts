import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { UNIT_ROUNDOFF } from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { World } from "./world.js";

/**
 * A disc placed against a line, a segment or a point under gravity, at any slope, place, scale and
 * field, touching it to the last bits, a rounding away from it, or clearly apart, at rest or moving
 * slowly: either the World refuses it as a resting contact (or another Zeno state), or it moves
 * with the disc never inside the obstacle. Never a fall through it, never an endless bounce at the
 * rounding level (restingOnSlope.test.ts has the cases the audit of session 17 found). Prints its
 * seed; set FC_SEED to explore others.
 */
const SEED = Number(process.env.FC_SEED ?? 20261123);
/** How deep inside an obstacle a disc may be seen: the slack an edit allows (OVERLAP_REL) and more. */
const INSIDE = 1e-8;

interface Case {
  kind: "line" | "segment" | "point";
  deg: number;
  cx: number;
  cy: number;
  r: number;
  g: number;
  gravityDeg: number;
  /** gap from touching, in units of r: 0, a few roundings either way, or clearly apart */
  gap: number;
  /** velocity along the normal (out of the obstacle) and along it, in units of sqrt(g r) */
  vn: number;
  vt: number;
}

/** A double in [min, max], tiny ones (which a World refuses as underflowing) as 0. */
const num = (min: number, max: number) =>
  fc.double({ min, max, noNaN: true }).map((x) => (Math.abs(x) < 1e-20 ? 0 : x));

const arbCase: fc.Arbitrary<Case> = fc.record({
  kind: fc.constantFrom("line" as const, "segment" as const, "point" as const),
  deg: fc.integer({ min: -80_000, max: 80_000 }).map((k) => k / 1000),
  cx: num(-1000, 1000),
  cy: num(-1000, 1000),
  r: fc.double({ min: 0.01, max: 100, noNaN: true }),
  g: fc.double({ min: 0.1, max: 100, noNaN: true }),
  gravityDeg: fc.integer({ min: -30_000, max: 30_000 }).map((k) => k / 1000),
  gap: fc.oneof(
    fc.constant(0),
    fc.integer({ min: -8, max: 8 }).map((k) => k * UNIT_ROUNDOFF),
    fc.double({ min: 1e-3, max: 1, noNaN: true }),
  ),
  // a rise of at most 5e-19 r (within any rounding of the gap), or of 5e-7 r and more: a rise in
  // between is a true elastic bounce, too low to be worth a run of millions of events here
  vn: fc.oneof(
    fc.constant(0),
    num(-1e-9, 1e-9),
    fc.tuple(fc.boolean(), fc.double({ min: 1e-3, max: 1, noNaN: true })).map(([up, v]) => (up ? v : -v)),
  ),
  vt: fc.oneof(fc.constant(0), num(-1, 1)),
});

/** The world of a case, and the disc's distance to the obstacle minus r, in units of r. */
function build(c: Case): { w: World; gapOf: () => number } {
  const a = (c.deg * Math.PI) / 180;
  // the obstacle's outward normal (towards the disc): up, tilted by deg
  const nx = Math.sin(a);
  const ny = Math.cos(a);
  const ga = (c.gravityDeg * Math.PI) / 180;
  const w = new World({ g: 0, gravity: [c.g * Math.sin(ga), -c.g * Math.cos(ga)] });
  const L = 50 * c.r;
  if (c.kind === "point") w.addPoint("o", [c.cx, c.cy]);
  else w.addLine("o", [c.cx - L * ny, c.cy + L * nx], [c.cx + L * ny, c.cy - L * nx], c.kind);
  const d = c.r * (1 + c.gap);
  const speed = Math.sqrt(c.g * c.r);
  w.addBody("ball", {
    x: c.cx + d * nx,
    y: c.cy + d * ny,
    r: c.r,
    m: 1,
    vx: speed * (c.vn * nx + c.vt * ny),
    vy: speed * (c.vn * ny - c.vt * nx),
  });
  const gapOf = () => {
    const b = w.body("ball");
    const dx = b.x - c.cx;
    const dy = b.y - c.cy;
    if (c.kind === "point") return (Math.hypot(dx, dy) - c.r) / c.r;
    const along = dx * ny - dy * nx;
    // past a segment's end the disc may fall beside it: only its side counts
    if (c.kind === "segment" && Math.abs(along) > L) return 0;
    return (Math.abs(dx * nx + dy * ny) - c.r) / c.r;
  };
  return { w, gapOf };
}

/** The refusals a case may end in: a resting contact, or another Zeno state. */
const REFUSAL = /rests against|Zeno state/;

/**
 * Runs a case: either refused (a resting contact or another Zeno state; any other error fails) or
 * never inside the obstacle, never an endless bounce. A case clearly apart (gap >= 1e-3 r) falls
 * and bounces elastically: it is never refused. Returns whether the case ran (was not refused).
 */
function check(c: Case): boolean {
  const { w, gapOf } = build(c);
  // about 40 bounces of the slowest case, and never more than 20,000 events a slice
  const T = 40 * Math.sqrt((8 * c.r) / c.g);
  let deepest = 0;
  try {
    for (let k = 1; k <= 512; k++) {
      const r = w.advance({ untilTime: (k * T) / 512, maxEvents: 20_000 }, () => {
        deepest = Math.min(deepest, gapOf());
      });
      deepest = Math.min(deepest, gapOf());
      expect(r.reason, "an endless bounce at the rounding level").not.toBe("events");
    }
  } catch (e) {
    if (!(e instanceof SimulationError) || !REFUSAL.test(e.message)) throw e;
    expect(c.gap, `a disc clearly apart was refused: ${e.message}`).toBeLessThan(1e-3);
    expect(deepest).toBeGreaterThanOrEqual(-INSIDE);
    return false;
  }
  expect(deepest).toBeGreaterThanOrEqual(-INSIDE);
  return true;
}

/** A disc touching a point, moving along the contact within k ulps of the speed that keeps it on. */
const arbCritical: fc.Arbitrary<Case> = fc
  .record({
    deg: fc.integer({ min: -60_000, max: 60_000 }).map((k) => k / 1000),
    gravityDeg: fc.integer({ min: -20_000, max: 20_000 }).map((k) => k / 1000),
    cx: num(-100, 100),
    cy: num(-100, 100),
    r: fc.constantFrom(0.01, 1, 3.7),
    g: fc.constantFrom(0.1, 1, 9.81),
    k: fc.oneof(fc.integer({ min: -16, max: 16 }), fc.constantFrom(-1e7, -1e3, 1e3, 1e7)),
    back: fc.boolean(),
  })
  .map(({ deg, gravityDeg, cx, cy, r, g, k, back }) => {
    // the pull of gravity towards the point, in units of g: cos of the angle between the two
    const pull = Math.cos(((deg + gravityDeg) * Math.PI) / 180);
    const vt = Math.sqrt(pull) * (1 + k * 2 ** -52) * (back ? -1 : 1);
    return { kind: "point" as const, deg, cx, cy, r, g, gravityDeg, gap: 0, vn: 0, vt };
  });

/**
 * Checks `numRuns` cases of `arb` and returns how many ran (were not refused): a refusal passes, so
 * the callers require a least number that ran (review of session 20: 169 of 400 were refused, and a
 * regression refusing them all would have passed).
 */
function casesThatRan(arb: fc.Arbitrary<Case>, numRuns: number): number {
  let ran = 0;
  fc.assert(
    fc.property(arb, (c) => {
      if (check(c)) ran++;
    }),
    { seed: SEED, numRuns },
  );
  return ran;
}

describe("a disc against an obstacle under gravity", () => {
  it("is refused as resting, or moves without ever going inside it", () => {
    console.log(`[resting contact] fast-check seed ${SEED} (set FC_SEED to change)`);
    // 231 ran with the default seed
    expect(casesThatRan(arbCase, 400)).toBeGreaterThanOrEqual(100);
  });

  it("crossing a peg within a few ulps to 1e-9 of the speed that keeps it on: refused, or never inside it", () => {
    // review of session 17: at about that speed discs sank into the peg or looped at one instant;
    // 96 of 300 ran with the default seed
    expect(casesThatRan(arbCritical, 300)).toBeGreaterThanOrEqual(40);
  });
});
