// Property: a frame evaluated at another time inside its bodies' motion-law intervals (frameAt over
// markValidity) agrees with the engine's exact stateAt of that time.
import { billiardsBreak, bouncingBalls, brownian, originalDemo, Timeline } from "@chapgame/engine";
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { packFrame } from "../remote/packFrame";
import { F_FROM, F_UNTIL, F_VX, F_VY, F_X, F_Y, FRAME_STRIDE } from "../remote/protocol";
import { markValidity } from "../remote/validity";
import { seedFor } from "../testing/seed";
import { emptyFrame, frameAt } from "./frameAt";

const SEED = seedFor("frameAt.prop.test");

const scenes = { originalDemo, bouncingBalls, billiardsBreak, brownian };
const timelines = new Map<string, Timeline>();
function timeline(name: keyof typeof scenes): Timeline {
  let tl = timelines.get(name);
  if (!tl) {
    tl = Timeline.fromScene(scenes[name]());
    tl.prolong({ time: 6 });
    timelines.set(name, tl);
  }
  return tl;
}

let total = 0;

describe("frameAt", () => {
  it("inside each body's interval, equals stateAt (friction, gravity, collisions, stops)", () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...(Object.keys(scenes) as (keyof typeof scenes)[])),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0.01, max: 2, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
        (name, u, window, v) => {
          const tl = timeline(name);
          const h = tl.horizon;
          const t0 = u * h;
          const base = packFrame(tl.stateAt(t0), 0);
          const index = new Map(base.ids.map((id, i) => [id, i]));
          markValidity(
            base.data,
            index,
            tl.eventsBetween(Math.max(0, t0 - window), Math.min(h, t0 + window)),
            t0,
            window,
            h,
          );
          const t = Math.min(h, Math.max(0, t0 + v * window));
          const f = frameAt(base, t, emptyFrame());
          const exact = tl.stateAt(t);
          let checked = 0;
          for (let i = 0; i < base.ids.length; i++) {
            const o = i * FRAME_STRIDE;
            const from = base.data[o + F_FROM]!;
            const until = base.data[o + F_UNTIL]!;
            expect(from).toBeLessThanOrEqual(t0);
            expect(until).toBeGreaterThanOrEqual(t0);
            if (t < from || t > until) continue;
            const b = exact.bodies.find((x) => x.id === base.ids[i])!;
            const tol = 1e-9 * (1 + Math.abs(b.x) + Math.abs(b.y) + Math.abs(b.vx) + Math.abs(b.vy));
            expect(Math.abs(f.data[o + F_X]! - b.x)).toBeLessThanOrEqual(tol);
            expect(Math.abs(f.data[o + F_Y]! - b.y)).toBeLessThanOrEqual(tol);
            // at an interval's end the velocity may already be the one after the event
            if (t < until) {
              expect(Math.abs(f.data[o + F_VX]! - b.vx)).toBeLessThanOrEqual(tol);
              expect(Math.abs(f.data[o + F_VY]! - b.vy)).toBeLessThanOrEqual(tol);
            }
            checked++;
          }
          total += checked;
        },
      ),
      { seed: SEED, numRuns: 300, verbose: true },
    );
    expect(total).toBeGreaterThan(300); // bodies were compared, not all skipped
  });

  it("a body whose interval ended waits at its end; the frame's own time is the frame", () => {
    const tl = timeline("billiardsBreak");
    const base = packFrame(tl.stateAt(0.5), 0);
    markValidity(
      base.data,
      new Map(base.ids.map((id, i) => [id, i])),
      tl.eventsBetween(0, 1),
      0.5,
      0.5,
      tl.horizon,
    );
    const same = frameAt(base, 0.5, emptyFrame());
    expect([...same.data]).toEqual([...base.data]);
    const later = frameAt(base, 5, emptyFrame());
    const atEnd = frameAt(base, 1, emptyFrame());
    expect([...later.data]).toEqual([...atEnd.data]);
  });
});
