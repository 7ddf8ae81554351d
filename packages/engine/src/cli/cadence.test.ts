// The pace of the computation on a clock (cadence.ts), given as elapsed times: no real time is waited.
import { describe, expect, it } from "vitest";
import {
  clockCadence,
  eventCadence,
  FIRST_REPORT_MS,
  nextSliceBudget,
  PROGRESS_EVERY_EVENTS,
  REPORT_EVERY_MS,
  SLICE_EVENTS,
  SLICE_TARGET_MS,
} from "./cadence.js";

describe("clockCadence", () => {
  it("is first due FIRST_REPORT_MS into the computation, then REPORT_EVERY_MS after each line", () => {
    const c = clockCadence();
    expect(c.due(0, 0)).toBe(false);
    expect(c.due(0, FIRST_REPORT_MS - 1)).toBe(false);
    expect(c.due(0, FIRST_REPORT_MS)).toBe(true);
    expect(c.due(0, FIRST_REPORT_MS + 1)).toBe(false);
    expect(c.due(0, FIRST_REPORT_MS + REPORT_EVERY_MS - 1)).toBe(false);
    expect(c.due(0, FIRST_REPORT_MS + REPORT_EVERY_MS)).toBe(true);
  });

  it("counts the next period from the line, so a slice that ran long gives one line, not a burst", () => {
    const c = clockCadence();
    expect(c.due(0, 7_000)).toBe(true); // one slice took 7 seconds
    expect(c.due(0, 7_000)).toBe(false);
    expect(c.due(0, 7_000 + REPORT_EVERY_MS - 1)).toBe(false);
    expect(c.due(0, 7_000 + REPORT_EVERY_MS)).toBe(true);
  });

  it("does not depend on the events: a fast run is not shown more often, a slow one not less", () => {
    for (const perSlice of [1, 10_000, 1e9]) {
      const c = clockCadence();
      const due: number[] = [];
      for (let ms = 100; ms <= 3_000; ms += 100) if (c.due(perSlice * (ms / 100), ms)) due.push(ms);
      expect(due).toEqual([500, 1_500, 2_500]);
    }
  });
});

describe("eventCadence (no clock)", () => {
  it("is due each time the events reach the next multiple of PROGRESS_EVERY_EVENTS, whatever the time", () => {
    const c = eventCadence();
    expect(c.due(PROGRESS_EVERY_EVENTS - 1, 1e9)).toBe(false);
    expect(c.due(PROGRESS_EVERY_EVENTS, Number.NaN)).toBe(true);
    expect(c.due(PROGRESS_EVERY_EVENTS + 1, Number.NaN)).toBe(false);
    // a jump over several multiples gives one line, and the next at the multiple after it
    expect(c.due(3.5 * PROGRESS_EVERY_EVENTS, Number.NaN)).toBe(true);
    expect(c.due(4 * PROGRESS_EVERY_EVENTS - 1, Number.NaN)).toBe(false);
    expect(c.due(4 * PROGRESS_EVERY_EVENTS, Number.NaN)).toBe(true);
  });
});

describe("nextSliceBudget", () => {
  it("scales a slice that ran long down to last about SLICE_TARGET_MS, to at least 1 event", () => {
    expect(nextSliceBudget(SLICE_EVENTS, 6_000)).toBe(Math.floor((SLICE_EVENTS * SLICE_TARGET_MS) / 6_000));
    expect(nextSliceBudget(1_000, 4 * SLICE_TARGET_MS)).toBe(250);
    expect(nextSliceBudget(3, 1e6)).toBe(1);
  });

  it("doubles a short slice's budget back up to SLICE_EVENTS, keeps one near the target", () => {
    expect(nextSliceBudget(1_000, SLICE_TARGET_MS / 2 - 1)).toBe(2_000);
    expect(nextSliceBudget(SLICE_EVENTS / 2 + 1, 0)).toBe(SLICE_EVENTS);
    expect(nextSliceBudget(SLICE_EVENTS, 0)).toBe(SLICE_EVENTS);
    expect(nextSliceBudget(700, SLICE_TARGET_MS / 2)).toBe(700);
    expect(nextSliceBudget(700, SLICE_TARGET_MS)).toBe(700);
  });

  it("settles within a few slices on a scene of any cost per event, each slice then near the target", () => {
    for (const msPerEvent of [1e-4, 0.01, 0.6, 50]) {
      let budget = 1_000;
      for (let i = 0; i < 20; i++) budget = nextSliceBudget(budget, budget * msPerEvent);
      const ms = budget * msPerEvent;
      if (budget === SLICE_EVENTS) expect(ms).toBeLessThanOrEqual(SLICE_TARGET_MS);
      else if (budget === 1) expect(ms).toBeGreaterThan(SLICE_TARGET_MS / 2);
      else {
        expect(ms, String(msPerEvent)).toBeGreaterThanOrEqual(SLICE_TARGET_MS / 2 - msPerEvent);
        expect(ms, String(msPerEvent)).toBeLessThanOrEqual(SLICE_TARGET_MS);
      }
    }
  });
});
