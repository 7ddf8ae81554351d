import { describe, expect, it } from "vitest";
import type { LineKind } from "./obstacles.js";
import { World } from "./world.js";

/**
 * Discs in tilted channels of rays or segments exactly their diameter wide (contactTimes.ts
 * endTime, tolerances.ts END_INSIDE_SLACK and GRAZE_SLACK). The walls' ends lie on the lines the
 * disc's edges move along, so the exact gap to an end touches 0 and never crosses it; rounded, it
 * dipped below 0 and the end took a tiny impulse that set the disc bouncing between the two walls
 * it touched: a Zeno error at the channel's end (session 25: 4,379 of 5,844 tilted channels failed
 * so, on segments). The axis-parallel channel is exact: channel.test.ts.
 */
type Motion = "slide" | "uniform" | "fall";

interface Channel {
  world: World;
  ends: [number, number][];
}

/** A channel at `deg` degrees, walls `len` long from the origin on (and `back` behind it), a disc r. */
function channel(
  deg: number,
  motion: Motion,
  kind: LineKind,
  r: number,
  len: number,
  start: number,
): Channel {
  const a = (deg * Math.PI) / 180;
  const c = Math.cos(a);
  const s = Math.sin(a);
  const world = new World(
    motion === "fall"
      ? { g: 0, gravity: [9.81 * c, 9.81 * s] }
      : { g: motion === "slide" ? 9.81 : 0, gravity: [0, 0] },
  );
  const ends: [number, number][] = [];
  for (const side of [-1, 1]) {
    const p1: [number, number] = [-s * side * r - len * c, c * side * r - len * s];
    const p2: [number, number] = [-s * side * r + len * c, c * side * r + len * s];
    ends.push(p1, p2);
    world.addLine(`w${side}`, p1, p2, kind);
  }
  const speed = motion === "fall" ? 0 : 80;
  const mu = motion === "slide" ? 0.01 : 0;
  world.addBody("d", { x: start * c, y: start * s, r, m: 1, mu, vx: speed * c, vy: speed * s });
  return { world, ends };
}

/** Runs the channel; the events at a wall's end, and the error if the run threw. */
function run(ch: Channel, untilTime: number): { endEvents: number; error: string | null } {
  let endEvents = 0;
  try {
    ch.world.advance({ untilTime, maxEvents: 10_000 }, (e) => {
      if (ch.ends.some(([x, y]) => x === e.px && y === e.py)) endEvents++;
    });
    return { endEvents, error: null };
  } catch (err) {
    return { endEvents, error: (err as Error).message };
  }
}

const ANGLES = Array.from({ length: 50 }, (_, k) => 0.37 + 7.21 * k);

describe("a disc in a tilted channel exactly its diameter wide", () => {
  it("slides under friction past the end of 10^4-long segments at 30 degrees (was a Zeno error)", () => {
    const ch = channel(30, "slide", "segment", 1, 1e4, 0);
    const events: string[] = [];
    ch.world.advance({ untilTime: 2000 }, (e) => events.push(e.kind));
    expect(events).toEqual(["stop"]);
    const d = ch.world.body("d");
    // it stops where friction stops it: 80^2 / (2 mu g) along the channel
    expect(Math.hypot(d.x, d.y)).toBeCloseTo(80 ** 2 / (2 * 0.01 * 9.81), 6);
  });

  for (const kind of ["segment", "ray"] as const)
    for (const motion of ["slide", "uniform"] as const)
      it(`${motion}s along ${kind}s at 50 angles, from inside and from outside, never touching an end`, () => {
        for (const deg of ANGLES)
          for (const start of [0, -(100 + 20)]) {
            const result = run(channel(deg, motion, kind, 0.7, 100, start), 10);
            expect({ deg, start, ...result }).toEqual({ deg, start, endEvents: 0, error: null });
          }
      });

  it("falls from rest along segments at 50 angles without touching an end or a Zeno error", () => {
    for (const deg of ANGLES) {
      const result = run(channel(deg, "fall", "segment", 0.3, 100, 0), 10);
      expect({ deg, endEvents: result.endEvents }).toEqual({ deg, endEvents: 0 });
      // the rounding of gravity's direction may press the disc into a wall: refused as resting
      // (the model has no sliding contact under an acceleration), never a Zeno error
      if (result.error !== null) expect(result.error).toMatch(/rests against/);
    }
  });
});

describe("the ends of tilted walls still stop what really hits them", () => {
  const a = (23 * Math.PI) / 180;
  const c = Math.cos(a);
  const s = Math.sin(a);

  it("a disc running head-on into a segment's end along its line bounces straight back", () => {
    const w = new World({ g: 0 });
    w.addLine("w", [0, 0], [10 * c, 10 * s], "segment");
    w.addBody("d", { x: -5 * c, y: -5 * s, r: 1, m: 1, vx: 2 * c, vy: 2 * s });
    const hits: { b: string | null; px: number; py: number }[] = [];
    w.advance({ untilTime: 10 }, (e) => hits.push({ b: e.b, px: e.px, py: e.py }));
    expect(hits).toEqual([{ b: "w", px: 0, py: 0 }]);
    const d = w.body("d");
    expect(d.vx).toBeCloseTo(-2 * c, 12);
    expect(d.vy).toBeCloseTo(-2 * s, 12);
  });

  it("a disc passing a segment's end at 0.9 r from its centre line hits the end", () => {
    const w = new World({ g: 9.81 });
    w.addLine("w", [0, 0], [10 * c, 10 * s], "segment");
    // beyond the end, moving along the line, offset 0.9 across it
    w.addBody("d", { x: -5 * c - 0.9 * s, y: -5 * s + 0.9 * c, r: 1, m: 1, mu: 0.01, vx: 3 * c, vy: 3 * s });
    const hits: { b: string | null; px: number; py: number }[] = [];
    w.advance({ untilTime: 10 }, (e) => {
      if (e.kind !== "stop") hits.push({ b: e.b, px: e.px, py: e.py });
    });
    expect(hits[0]).toEqual({ b: "w", px: 0, py: 0 });
  });
});
