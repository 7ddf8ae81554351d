/**
 * Helpers for the World's tests (not built, not packed): the totals a collision must keep, the
 * break of a rack of touching discs (a scene that found several rounding defects), a pit an
 * immovable disc passes over, the run to a Zeno report and the bound on its events (the trap and
 * line watches' tests), the pop order of an event queue, and the error a refused call throws.
 */
import fc from "fast-check";
import { expect } from "vitest";
import type { CalendarQueue } from "./calendarQueue.js";
import { ChapgameError } from "./errors.js";
import type { BodyState } from "./types.js";
import { World } from "./world.js";

/** Kinetic energy and momentum of the bodies: { energy, px, py }. */
export function totals(bodies: readonly BodyState[]): { energy: number; px: number; py: number } {
  let energy = 0;
  let px = 0;
  let py = 0;
  for (const s of bodies) {
    energy += 0.5 * s.m * (s.vx * s.vx + s.vy * s.vy);
    px += s.m * s.vx;
    py += s.m * s.vy;
  }
  return { energy, px, py };
}

/** A disc to add: `World.addBody(id, disc)`. */
export interface RackDisc {
  x: number;
  y: number;
  r: number;
  m: number;
  mu: number;
  vx?: number;
}

/**
 * The break of an n x n rack of exactly touching discs (radius 2.5, 6 apart in a row, each row
 * offset by (3, 4): contacts 3-4-5, exact in doubles; masses 1 to 4) by a cue ball of mass 2 from
 * (-20, 4 floor(n / 2) + cueOffset) at speed `cueSpeed` along x; every disc with friction `mu`.
 * Ids `kJJ_II` and `cue`, in the order to add them.
 */
export function rackBreak(n: number, mu: number, cueOffset: number, cueSpeed: number): [string, RackDisc][] {
  const adds: [string, RackDisc][] = [];
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++)
      adds.push([
        `k${String(j).padStart(2, "0")}_${String(i).padStart(2, "0")}`,
        { x: 6 * i + 3 * j, y: 4 * j, r: 2.5, m: 1 + ((i * 7 + j * 3) % 4), mu },
      ]);
  adds.push(["cue", { x: -20, y: 4 * Math.floor(n / 2) + cueOffset, r: 2.5, m: 2, mu, vx: cueSpeed }]);
  return adds;
}

/** The smallest distance between the centres of two of the bodies (all pairs: for small tests). */
export function minCentreDistance(bodies: readonly BodyState[]): number {
  let best = Number.POSITIVE_INFINITY;
  for (let i = 0; i < bodies.length; i++)
    for (let j = i + 1; j < bodies.length; j++) {
      const p = bodies[i] as BodyState;
      const q = bodies[j] as BodyState;
      best = Math.min(best, Math.hypot(p.x - q.x, p.y - q.y));
    }
  return best;
}

/**
 * A V pit (sides at 45° up to height 2) holding a disc (r 1) under gravity 0.05, and an immovable
 * disc (R 1) crossing above it on a parabola whose apex is `gap` above closing the pit on the disc
 * (negative: it dips into the pocket, a crush).
 */
export function pit(gap: number): World {
  const g = 0.05;
  const w = new World({ g: 0, gravity: [0, -g] });
  w.addLine("left", [-2, 2], [0, 0], "segment");
  w.addLine("right", [0, 0], [2, 2], "segment");
  w.addBody("d", { x: 0.1, y: 1.6, r: 1, m: 1 });
  const apex = Math.SQRT2 + 2 + gap; // the disc's lowest spot is (0, sqrt 2)
  const T = 8;
  w.addBody("p", { x: T, y: apex - 0.5 * g * T * T, r: 1, m: Number.POSITIVE_INFINITY, vx: -1, vy: g * T });
  return w;
}

/** The bound the trap watch's tests assert on events before a crush is reported (measured: 256 to 2,560). */
export const TRAP_REPORT_BOUND = 5000;

/** Advance until the World throws (or `maxEvents` events): the error (null if none) and the events before it. */
export function runToError(w: World, maxEvents = 10_000_000): { error: unknown; events: number } {
  let events = 0;
  try {
    w.advance({ maxEvents }, () => events++);
  } catch (error) {
    return { error, events };
  }
  return { error: null, events };
}

// The placement checks' property tests (sim/placementIndex, scene/sceneRulesIndex): the same frames and places.
/** A frame: coordinates o + s·u (far off, tiny, or plain), and the base discs' radius in units. */
export const placementFrame = fc
  .record({
    os: fc.constantFrom(
      [0, 1],
      [0, 1],
      [1e6, 1],
      [-1e12, 1],
      [3e15, 4],
      [1e29, 1e18],
      [0, 1e-6],
      [1e6, 1e-6],
    ),
    rho: fc.constantFrom(0.5, 1, 1.9),
  })
  .map(({ os, rho }) => ({ o: os[0] as number, s: os[1] as number, rho }));
export const placementUnit = fc.integer({ min: -40, max: 40 }).map((k) => k / 2);
const placementGap = fc.constantFrom(0, 0, 3e-10, -3e-10, 1e-9, -1e-9, 2e-9, -2e-9, 1e-3, -0.3, 0.5);
/** A place: a lattice point, or touching body/line/point number `near` (mod their count) up to `gap`. */
export const placementPlace = fc.record({
  u: fc.tuple(placementUnit, placementUnit),
  near: fc.oneof(fc.constant(-1), fc.nat(200)),
  what: fc.constantFrom("body", "line", "point"),
  end: fc.constantFrom(0, 0.5, 1),
  angle: fc.constantFrom(0, 1, 2, 3, 0.5),
  gap: placementGap,
});
export type PlacementPlace = typeof placementPlace extends fc.Arbitrary<infer P> ? P : never;
/** A line's far end: near the lattice, or far off (a long wall across many cells). */
export const placementFarEnd = fc.oneof(
  fc.tuple(placementUnit, placementUnit),
  fc.tuple(fc.integer({ min: -900, max: 900 }), fc.integer({ min: -900, max: 900 })),
);
/** Add or move point p<id> to a place. */
export const placementPointStep = fc.record({
  op: fc.constant("point" as const),
  id: fc.integer({ min: 0, max: 47 }),
  place: placementPlace,
});

/** Pop every slot of the queue, earliest first (peek, then remove): its whole pop order. */
export function drain(q: CalendarQueue): number[] {
  const out: number[] = [];
  while (q.size > 0) {
    const s = q.peek();
    out.push(s);
    q.remove(s);
  }
  return out;
}

/** The ChapgameError `run` throws; fails the test when `run` is accepted or throws anything else. */
export function refusal(run: () => unknown): ChapgameError {
  try {
    run();
  } catch (e) {
    expect(e).toBeInstanceOf(ChapgameError);
    return e as ChapgameError;
  }
  throw new Error("accepted");
}
