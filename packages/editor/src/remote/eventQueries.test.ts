import { newtonsCradle, originalDemo, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { eventPage, eventTicks, lastEventTime } from "./eventQueries";
import { exactSeries, SeriesRecorder } from "./series";

/** Newton's cradle computed 10 s: 6 actions at 0, then 5 collisions at t = 1. */
function cradle() {
  const tl = Timeline.fromScene(newtonsCradle(), { compute: false });
  tl.prolong({ time: 10 });
  return tl;
}

describe("event queries", () => {
  it("a page holds the events at or before t and after t, in time order", () => {
    const tl = cradle();
    const all = tl.eventsBetween(0, tl.horizon);
    const page = eventPage(tl, 0.5, 3, 2, null);
    expect(page.total).toBe(tl.eventCount);
    expect(page.events).toEqual([
      ...all.filter((e) => e.time <= 0.5).slice(-3),
      ...all.filter((e) => e.time > 0.5).slice(0, 2),
    ]);
  });

  it("the body filter keeps only that body's events on both sides", () => {
    const tl = cradle();
    const page = eventPage(tl, 0.5, 10, 10, "c3");
    expect(page.events.map((e) => [e.time, e.type])).toEqual([
      [0, "action"],
      [1, "bodyBody"],
      [1, "bodyBody"],
    ]);
    expect(page.events.every((e) => e.ids.includes("c3"))).toBe(true);
  });

  it("filtered at t = 0, a page holds the body's events at time 0 (its add body)", () => {
    const tl = cradle();
    const page = eventPage(tl, 0, 10, 10, "c3");
    expect(page.events.map((e) => [e.time, e.type])).toEqual([
      [0, "action"],
      [1, "bodyBody"],
      [1, "bodyBody"],
    ]);
  });

  it("ticks mark the first event of every bin that has one", () => {
    const tl = Timeline.fromScene(originalDemo(), { compute: false });
    tl.prolong({ time: 10 });
    const times = tl.eventsBetween(0, tl.horizon).map((e) => e.time);
    const ticks = eventTicks(tl, 100);
    expect(ticks.length).toBeGreaterThan(0);
    for (const t of ticks) expect(times).toContain(t);
    expect(ticks).toEqual([...new Set(ticks)].sort((a, b) => a - b));
    expect(eventTicks(tl, 100)[0]).toBe(0);
  });
});

describe("lastEventTime", () => {
  it("is the time of the last logged event, also when it is at the horizon", () => {
    const tl = cradle();
    expect(lastEventTime(tl)).toBe(1);
    const empty = new Timeline();
    expect(lastEventTime(empty)).toBeNull();
    const demo = Timeline.fromScene(originalDemo(), { compute: false });
    demo.prolong({ time: 0 });
    expect(demo.eventCount).toBeGreaterThan(0);
    expect(lastEventTime(demo)).toBe(0);
  });
});

describe("SeriesRecorder", () => {
  it("records energy and event count at the horizon, and forgets samples after a cut", () => {
    const tl = cradle();
    const r = new SeriesRecorder();
    r.record(tl);
    const [p] = r.points(10);
    expect(p).toEqual({ t: 10, energy: 0.5 * 1 * 16, collisions: tl.eventCount });
    r.cut(5);
    expect(r.points(10)).toEqual([]);
  });
});

describe("exactSeries", () => {
  it("counts the logged events up to each sample time; the cradle keeps its energy", () => {
    const tl = cradle();
    const s = exactSeries(tl, 10);
    expect(s.map((p) => p.t)).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
    expect(s.map((p) => p.collisions)).toEqual([6, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11]);
    for (const p of s) expect(p.energy).toBe(8);
  });
});
