/**
 * Restart points in long histories: an edit in the past recomputes from the last keyframe before it,
 * whose World is rebuilt from the keyframe's motions (keyframe.ts worldAt), and must give exactly
 * what building the edited scene from scratch gives. Gases of 40–120 discs (the broad-phase grid
 * active, keyframes every few hundred to thousand events), with and without friction. Logs its seed
 * (fixed by default so CI is reproducible); explore others with FC_SEED=<n>.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { Action, SceneFile } from "../scene/types.js";
import { seedFor } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const RUNS = Number(process.env.RUNS ?? 8);
const seed = seedFor("restart");

/** The gas, with every disc given the friction coefficient mu (0: elastic). */
function gasScene(n: number, gasSeed: number, mu: number): SceneFile {
  const s = dilutedGas({ n, packing: 0.15, seed: gasSeed });
  return {
    ...s,
    g: mu > 0 ? 1 : s.g,
    actions: s.actions.map((a) => (a.type === "addBody" ? { ...a, mu } : a)),
  };
}

describe("Timeline restarts from keyframes rebuilt from motions", () => {
  it("an edit deep in a long history equals building the edited scene from scratch", () => {
    let keyframesBefore = 0;
    fc.assert(
      fc.property(
        fc.integer({ min: 40, max: 120 }),
        fc.integer({ min: 1, max: 1000 }),
        fc.constantFrom(0, 0.001),
        fc.double({ min: 0.3, max: 0.999, noNaN: true }),
        fc.nat(),
        // Speeds below SPEED_MIN are refused (sim/magnitude.test.ts); this property is about restarts.
        fc.tuple(
          fc.oneof(
            fc.constant(0),
            fc.double({ min: 1e-3, max: 1, noNaN: true }),
            fc.double({ min: -1, max: -1e-3, noNaN: true }),
          ),
          fc.oneof(
            fc.constant(0),
            fc.double({ min: 1e-3, max: 1, noNaN: true }),
            fc.double({ min: -1, max: -1e-3, noNaN: true }),
          ),
        ),
        (n, gasSeed, mu, frac, who, v) => {
          const s = gasScene(n, gasSeed, mu);
          const tl = Timeline.fromScene(s);
          tl.prolong({ events: 15_000 });
          const H = tl.horizon;
          const time = frac * H;
          keyframesBefore += tl.eventsBetween(0, time).length > 2000 ? 1 : 0;
          const ids = tl.stateAt(0).bodies.map((b) => b.id);
          const action: Action = { time, type: "giveVelocity", id: ids[who % ids.length] as string, v };
          tl.apply(action);
          const scratch = Timeline.fromScene({ ...s, actions: [...s.actions, action] });
          scratch.prolongTo(H);
          expect(tl.eventsBetween(time, H)).toStrictEqual(scratch.eventsBetween(time, H));
          expect(tl.stateAt(H)).toStrictEqual(scratch.stateAt(H));
          expect(tl.stateAt((time + H) / 2)).toStrictEqual(scratch.stateAt((time + H) / 2));
          expect(tl.counts()).toStrictEqual(scratch.counts());
          // Undo through setActions restarts from a keyframe too.
          tl.setActions(s.actions);
          const original = Timeline.fromScene(s);
          original.prolongTo(H);
          expect(tl.eventsBetween(time, H)).toStrictEqual(original.eventsBetween(time, H));
          expect(tl.stateAt(H)).toStrictEqual(original.stateAt(H));
        },
      ),
      { seed, numRuns: RUNS, verbose: true },
    );
    // Most edits must land after several keyframes (restarts from the middle of the history).
    expect(keyframesBefore).toBeGreaterThanOrEqual(RUNS / 2);
  });
});
