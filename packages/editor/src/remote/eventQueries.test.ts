import { newtonsCradle, originalDemo, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { sceneOf } from "../testing/scenes";
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
    // the log's entries (action entries also say which action: see below)
    expect(page.events).toMatchObject([
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

  it("a pair filter ('c3, c4') keeps only the entries both take part in", () => {
    const tl = cradle();
    const page = eventPage(tl, 0.5, 10, 10, "c4, c3");
    expect(page.events.map((e) => [e.time, e.type, [...e.ids].sort()])).toEqual([
      [1, "bodyBody", ["c3", "c4"]],
    ]);
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

  it("ticks over a sub-range [lo, hi] (the zoomed Time slider) bin that range only", () => {
    // a disc bouncing between two walls: a collision every 0.1 s
    const tl = Timeline.fromScene(
      sceneOf(
        [
          { time: 0, type: "addLine", id: "left", p1: [-3, -5], p2: [-3, 5], kind: "line" },
          { time: 0, type: "addLine", id: "right", p1: [3, -5], p2: [3, 5], kind: "line" },
          { time: 0, type: "addBody", id: "a", x: 0.5, y: 0, r: 1, m: 1, v: [40, 0] },
        ],
        0,
      ),
      { compute: false },
    );
    tl.prolong({ time: 10 });
    const times = [...new Set(tl.eventsBetween(0, tl.horizon).map((e) => e.time))];
    // from an event's own time (it is included), 2 s on, in 10 bins of 0.2 s (two bounces each)
    const lo = times.find((t) => t > 3)!;
    const hi = lo + 2;
    const n = 10;
    // the first event of every bin of [lo, hi] that has one
    const expected: number[] = [];
    let bin = -1;
    for (const t of times.filter((t) => t >= lo && t <= hi)) {
      const k = Math.min(n - 1, Math.floor(((t - lo) / (hi - lo)) * n));
      if (k > bin) expected.push(t);
      bin = Math.max(bin, k);
    }
    expect(expected.length).toBe(n);
    expect(eventTicks(tl, n, lo, hi)).toEqual(expected);
    expect(eventTicks(tl, n, lo, hi)[0]).toBe(lo);
    // no range is the whole history; an empty range has no ticks
    expect(eventTicks(tl, n, 0, tl.horizon)).toEqual(eventTicks(tl, n));
    expect(eventTicks(tl, n, lo, lo)).toEqual([]);
  });
});

/**
 * Two actions at t = 1 (a given velocity, b moved away) after three at t = 0; a meets the point q
 * at t = 4.
 */
function twoAtOnce() {
  const tl = Timeline.fromScene(
    sceneOf(
      [
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
        { time: 0, type: "addBody", id: "b", x: 0, y: 10, r: 1, m: 1 },
        { time: 0, type: "addPoint", id: "q", p: [4, 0] },
        { time: 1, type: "giveVelocity", id: "a", v: [1, 0] },
        { time: 1, type: "updateBody", id: "b", x: 20 },
      ],
      0,
    ),
    { compute: false },
  );
  tl.prolong({ time: 10 });
  return tl;
}

/** The action entries of a page: time, action, id and actionIndex. */
function actionRows(
  events: { time: number; type: string; action?: string; ids: string[]; actionIndex?: number }[],
) {
  return events.filter((e) => e.type === "action").map((e) => [e.time, e.action, e.ids[0], e.actionIndex]);
}

describe("event pages name each action entry's action (actionIndex in the timeline's actions)", () => {
  it("every action entry, two of them at the same time; collisions carry none", () => {
    const tl = twoAtOnce();
    const page = eventPage(tl, 1, 10, 10, null);
    expect(actionRows(page.events)).toEqual([
      [0, "addBody", "a", 0],
      [0, "addBody", "b", 1],
      [0, "addPoint", "q", 2],
      [1, "giveVelocity", "a", 3],
      [1, "updateBody", "b", 4],
    ]);
    for (const e of page.events.filter((e) => e.type === "action"))
      expect(tl.actions[e.actionIndex!]).toMatchObject({ time: e.time, type: e.action, id: e.ids[0] });
    const hit = page.events.find((e) => e.type === "bodyPoint")!;
    expect(hit.time).toBe(4);
    expect("actionIndex" in hit).toBe(false);
  });

  it("a page that starts inside a group of entries at one time counts the group from its start", () => {
    const tl = twoAtOnce();
    // The last entry at or before t = 1: the second action at t = 1.
    expect(actionRows(eventPage(tl, 1, 1, 0, null).events)).toEqual([[1, "updateBody", "b", 4]]);
    // Four entries: from the second action at t = 0.
    expect(actionRows(eventPage(tl, 1, 4, 0, null).events)).toEqual([
      [0, "addBody", "b", 1],
      [0, "addPoint", "q", 2],
      [1, "giveVelocity", "a", 3],
      [1, "updateBody", "b", 4],
    ]);
    // Cut at the end inside the group at t = 0.
    expect(actionRows(eventPage(tl, -1, 0, 2, null).events)).toEqual([
      [0, "addBody", "a", 0],
      [0, "addBody", "b", 1],
    ]);
  });

  it("filtered by a body, its action entries keep their places among all the actions", () => {
    const tl = twoAtOnce();
    expect(actionRows(eventPage(tl, 1, 10, 10, "b").events)).toEqual([
      [0, "addBody", "b", 1],
      [1, "updateBody", "b", 4],
    ]);
    expect(actionRows(eventPage(tl, 1, 1, 10, "b").events)).toEqual([[1, "updateBody", "b", 4]]);
    expect(actionRows(eventPage(tl, 0, 10, 10, "q").events)).toEqual([[0, "addPoint", "q", 2]]);
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
