// How a computation request becomes a job of the host, or leaves the running one alone.
import { describe, expect, it } from "vitest";
import { nextBudget, planJob, SLICE_MS, targetOf } from "./computeJob";
import type { ComputeStatus } from "./protocol";

/** A running restore bringing the history back to t = 40. */
const restoring: ComputeStatus = {
  events: 10,
  targetEvents: null,
  targetTime: 40,
  startHorizon: 0,
  restore: true,
};

describe("targetOf", () => {
  it("counts a time limit from the horizon, or from `from`; none without one", () => {
    expect(targetOf({ until: { time: 10 } }, 5)).toBe(15);
    expect(targetOf({ until: { time: 10 }, from: 2 }, 5)).toBe(12);
    expect(targetOf({ until: { events: 10 } }, 5)).toBeNull();
    expect(targetOf({ until: null }, 5)).toBeNull();
  });
});

describe("planJob", () => {
  it("a time from the current time reached already needs nothing; from the horizon it always computes", () => {
    expect(planJob({ until: { time: 3 }, from: 2 }, false, null, 5)).toBe("reached");
    expect(planJob({ until: { time: 3 } }, false, null, 5)).toMatchObject({ targetTime: 8, restore: false });
    // a count of events always computes
    expect(planJob({ until: { time: 3, events: 5 }, from: 2 }, false, null, 5)).toMatchObject({
      targetEvents: 5,
    });
  });

  it("less than a running restore brings back leaves it running; a later time replaces it and stays a restore", () => {
    expect(planJob({ until: { time: 10 }, from: 20 }, false, restoring, 25)).toBe("covered");
    expect(planJob({ until: { time: 30 }, from: 20 }, false, restoring, 25)).toEqual({
      restore: true,
      events: 0,
      targetEvents: null,
      targetTime: 50,
      startHorizon: 25,
      budget: 256,
    });
    // events, or until idle, replace it as a plain computation
    expect(planJob({ until: { events: 5 } }, false, restoring, 25)).toMatchObject({ restore: false });
    expect(planJob({ until: null }, false, restoring, 25)).toMatchObject({
      restore: false,
      targetTime: null,
    });
    // a restore asked is one, even for less
    expect(planJob({ until: { time: 1 } }, true, restoring, 25)).toMatchObject({
      restore: true,
      targetTime: 26,
    });
  });
});

describe("nextBudget", () => {
  it("scales the budget so that a slice takes about SLICE_MS, within [16, 2^20]", () => {
    expect(nextBudget(300, 2 * SLICE_MS)).toBe(150);
    expect(nextBudget(300, SLICE_MS / 2)).toBe(600);
    expect(nextBudget(300, 0)).toBe(600); // too fast to measure: doubled
    expect(nextBudget(20, 100 * SLICE_MS)).toBe(16);
    expect(nextBudget(2 ** 20, 0)).toBe(2 ** 20);
  });
});
