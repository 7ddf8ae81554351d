// When a progress line is due (cadence.ts), on a clock given by the test: no real time is waited.
import { describe, expect, it } from "vitest";
import {
  clockCadence,
  eventCadence,
  FIRST_REPORT_MS,
  PROGRESS_EVERY_EVENTS,
  REPORT_EVERY_MS,
} from "./cadence.js";

/** A clock the test sets (milliseconds). */
function fakeClock(start: number) {
  const clock = { t: start, now: () => clock.t };
  return clock;
}

describe("clockCadence", () => {
  it("is first due FIRST_REPORT_MS after it is made, then REPORT_EVERY_MS after each line", () => {
    const clock = fakeClock(12_345.5); // the clock's origin is anywhere (performance.now)
    const c = clockCadence(clock.now);
    const at = (ms: number) => {
      clock.t = 12_345.5 + ms;
      return c.due(0);
    };
    expect(at(0)).toBe(false);
    expect(at(FIRST_REPORT_MS - 1)).toBe(false);
    expect(at(FIRST_REPORT_MS)).toBe(true);
    expect(at(FIRST_REPORT_MS + 1)).toBe(false);
    expect(at(FIRST_REPORT_MS + REPORT_EVERY_MS - 1)).toBe(false);
    expect(at(FIRST_REPORT_MS + REPORT_EVERY_MS)).toBe(true);
  });

  it("counts the next period from the line, so a slice that ran long gives one line, not a burst", () => {
    const clock = fakeClock(0);
    const c = clockCadence(clock.now);
    clock.t = 7_000; // one slice took 7 seconds
    expect(c.due(0)).toBe(true);
    expect(c.due(0)).toBe(false);
    clock.t = 7_000 + REPORT_EVERY_MS - 1;
    expect(c.due(0)).toBe(false);
    clock.t = 7_000 + REPORT_EVERY_MS;
    expect(c.due(0)).toBe(true);
  });

  it("does not depend on the events: a fast run is not shown more often, a slow one not less", () => {
    for (const events of [1, 10_000, 1e9]) {
      const clock = fakeClock(0);
      const c = clockCadence(clock.now);
      const due: number[] = [];
      for (let ms = 100; ms <= 3_000; ms += 100) {
        clock.t = ms;
        if (c.due(events * (ms / 100))) due.push(ms);
      }
      expect(due).toEqual([500, 1_500, 2_500]);
    }
  });
});

describe("eventCadence (no clock)", () => {
  it("is due each time the events reach the next multiple of PROGRESS_EVERY_EVENTS", () => {
    const c = eventCadence();
    expect(c.due(PROGRESS_EVERY_EVENTS - 1)).toBe(false);
    expect(c.due(PROGRESS_EVERY_EVENTS)).toBe(true);
    expect(c.due(PROGRESS_EVERY_EVENTS + 1)).toBe(false);
    // a jump over several multiples gives one line, and the next at the multiple after it
    expect(c.due(3.5 * PROGRESS_EVERY_EVENTS)).toBe(true);
    expect(c.due(4 * PROGRESS_EVERY_EVENTS - 1)).toBe(false);
    expect(c.due(4 * PROGRESS_EVERY_EVENTS)).toBe(true);
  });
});
