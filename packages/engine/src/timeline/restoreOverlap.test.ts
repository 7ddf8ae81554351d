/**
 * A Timeline restarts from its keyframes with the World's own motions, which may hold a pair
 * pressed together under friction and overlapping by more than OVERLAP_REL (README: what it cannot
 * do). Such a restart must not be refused as an overlapping edit.
 */
import { describe, expect, it } from "vitest";
import { SimulationError } from "../sim/errors.js";
import { minCentreDistance, rackBreak } from "../sim/testSupport.js";
import { World } from "../sim/world.js";
import { OVERLAP_REL } from "../tolerances.js";
import { Timeline } from "./timeline.js";

describe("Timeline restarts from keyframes that hold an overlap the World computed", () => {
  // Regression (review): in this rack break two discs overlap by 1.1e-8 of the contact distance
  // just before the push that ends the computation; an edit there rebuilt the World from a keyframe
  // with addBodyMotion, whose overlap check refused the World's own state ("the body would overlap
  // body 'k10_07'"), so every later edit and undo failed.
  it("an edit after the overlap formed is applied", () => {
    const tl = new Timeline({ g: 9.81 });
    tl.setActions(
      rackBreak(30, 0.1, 1.7, 40).map(([id, b]) => ({
        time: 0,
        type: "addBody" as const,
        id,
        x: b.x,
        y: b.y,
        r: b.r,
        m: b.m,
        mu: b.mu,
        v: [b.vx ?? 0, 0] as [number, number],
      })),
    );
    // Where the computation ends (the push), from a World; the Timeline computes to just before it.
    const w = new World({ g: 9.81 });
    for (const [id, b] of rackBreak(30, 0.1, 1.7, 40)) w.addBody(id, b);
    let end = Number.NaN;
    try {
      w.advance({});
    } catch (e) {
      expect(e).toBeInstanceOf(SimulationError);
      end = (e as SimulationError).time;
    }
    expect(end).toBeGreaterThan(2.9);
    tl.prolongTo(end - 1e-9);
    const at = end - 2e-9;
    // The state there holds an overlap beyond the round-off the edits accept.
    expect(minCentreDistance(tl.stateAt(at).bodies)).toBeLessThan(5 * (1 - OVERLAP_REL));
    tl.apply({ time: at, type: "addPoint", id: "far", p: [5000, 5000] });
    expect(tl.actions.at(-1)).toMatchObject({ id: "far" });
  });
});
