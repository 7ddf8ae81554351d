import { describe, expect, it } from "vitest";
import { advanceClock, canExtend, MAX_FRAME_SECONDS } from "./playback";

describe("advanceClock", () => {
  it("moves time by speed × elapsed, backwards for negative speeds", () => {
    expect(advanceClock(1, 2, 0.05, 10, false)).toEqual({ t: 1.1, stop: false });
    expect(advanceClock(1, -1, 0.05, 10, false)).toEqual({ t: 0.95, stop: false });
  });

  it("caps one step at MAX_FRAME_SECONDS of wall-clock time", () => {
    expect(advanceClock(0, 1, 5, 10, false).t).toBe(MAX_FRAME_SECONDS);
  });

  it("stops at 0 going backwards", () => {
    expect(advanceClock(0.01, -1, 0.05, 10, false)).toEqual({ t: 0, stop: true });
  });

  it("waits at the horizon while more can be computed, else stops there", () => {
    expect(advanceClock(9.99, 1, 0.05, 10, true)).toEqual({ t: 10, stop: false });
    expect(advanceClock(9.99, 1, 0.05, 10, false)).toEqual({ t: 10, stop: true });
  });

  it("holds a time past the horizon while the history is computed up to it, in either direction", () => {
    // after an undo at t = 10 the history is recomputed from 0: playing must not jump back to 1.9
    expect(advanceClock(10, 1, 0.05, 1.9, true)).toEqual({ t: 10, stop: false });
    expect(advanceClock(10, -1, 0.05, 1.9, true)).toEqual({ t: 10, stop: false });
    // nothing is computing any more (cancelled): go to the end of what there is, and stop there
    // forwards; backwards, play on from it (it stood still at 10 for ever: review of session 15)
    expect(advanceClock(10, 1, 0.05, 1.9, false)).toEqual({ t: 1.9, stop: true });
    expect(advanceClock(10, -1, 0.05, 1.9, false)).toEqual({ t: 1.9, stop: false });
  });
});

describe("canExtend", () => {
  const info = { idle: false, stopped: null };
  it("extends while auto-extend is on and more can be computed", () => {
    expect(canExtend(true, info)).toBe(true);
    expect(canExtend(false, info)).toBe(false);
    expect(canExtend(true, { ...info, idle: true })).toBe(false);
  });
  it("not after the engine refused to go on (playing at the horizon retried it forever)", () => {
    expect(canExtend(true, { ...info, stopped: "a Zeno state" })).toBe(false);
  });
});
