import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { LogEvent } from "../engineTypes";
import { F_FROM, F_UNTIL, FRAME_STRIDE } from "./protocol";
import { markValidity } from "./validity";

/** A log entry of this type and these participants (the contact fields do not matter here). */
const ev = (time: number, type: LogEvent["type"], ids: string[]): LogEvent =>
  type === "action"
    ? { time, type, ids, point: null, normal: null, impulse: null, action: "giveVelocity" }
    : type === "stop"
      ? { time, type, ids: [ids[0] as string], point: [0, 0], normal: null, impulse: 0 }
      : { time, type, ids: [ids[0] as string, ids[1] as string], point: [0, 0], normal: [1, 0], impulse: 1 };

function intervals(ids: string[], events: LogEvent[], t: number, window: number, horizon: number) {
  const data = new Float64Array(ids.length * FRAME_STRIDE);
  markValidity(data, new Map(ids.map((id, i) => [id, i])), events, t, window, horizon);
  return ids.map((_, i) => [data[i * FRAME_STRIDE + F_FROM], data[i * FRAME_STRIDE + F_UNTIL]]);
}

describe("markValidity", () => {
  it("a body's interval runs from its last event at or before t to its first event after t", () => {
    const events = [ev(1, "bodyBody", ["a", "b"]), ev(2, "bodyLine", ["b", "wall"]), ev(3.5, "stop", ["a"])];
    expect(intervals(["a", "b", "c"], events, 2, 10, 20)).toEqual([
      [1, 3.5],
      [2, 12], // its event at t itself starts its current law; nothing after it within the window
      [0, 12], // no event: the window, cut at 0
    ]);
  });

  it("an action ends every body's interval; the horizon caps them", () => {
    const events = [ev(0.5, "action", ["a"]), ev(1.5, "action", [])];
    expect(intervals(["a", "b"], events, 1, 5, 1.2)).toEqual([
      [0.5, 1.2],
      [0.5, 1.2],
    ]);
    expect(intervals(["a", "b"], events, 1, 5, 9)).toEqual([
      [0.5, 1.5],
      [0.5, 1.5],
    ]);
  });

  it("a zero window leaves every interval empty, at t", () => {
    expect(intervals(["a"], [ev(1, "bodyBody", ["a", "x"])], 1.25, 0, 9)).toEqual([[1.25, 1.25]]);
  });

  it("matches marking every body for every action, one event at a time (random logs)", () => {
    // The reference: each event in turn moves the interval ends of the bodies it involves (an
    // action: all bodies) towards t, as the first version did.
    const reference = (ids: string[], events: LogEvent[], t: number, w: number, h: number) => {
      const lo = Math.min(t, Math.max(0, t - w));
      const hi = Math.max(t, Math.min(h, t + w));
      return ids.map((id) => {
        let from = lo;
        let until = hi;
        for (const e of events) {
          if (e.time < lo || e.time > hi || (e.type !== "action" && !e.ids.includes(id))) continue;
          if (e.time <= t) from = Math.max(from, e.time);
          else until = Math.min(until, e.time);
        }
        return [from, until];
      });
    };
    const ids = ["a", "b", "c", "d"];
    const event = fc
      .record({
        time: fc.integer({ min: 0, max: 16 }).map((k) => k / 4),
        type: fc.constantFrom<LogEvent["type"]>("action", "bodyBody", "bodyLine", "stop"),
        a: fc.constantFrom(...ids, "gone"),
        b: fc.constantFrom(...ids),
      })
      .map((e) => ev(e.time, e.type, [e.a, e.b]));
    fc.assert(
      fc.property(
        fc.array(event, { maxLength: 12 }),
        fc.integer({ min: 0, max: 16 }).map((k) => k / 4),
        fc.integer({ min: 0, max: 8 }).map((k) => k / 4),
        fc.integer({ min: 0, max: 16 }).map((k) => k / 4),
        (events, t, w, h) => {
          events.sort((x, y) => x.time - y.time);
          expect(intervals(ids, events, t, w, h)).toEqual(reference(ids, events, t, w, h));
        },
      ),
    );
  });
});
