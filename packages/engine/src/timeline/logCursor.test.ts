/**
 * LogCursor: walking the log in order replays each record once, and whatever happens between two
 * reads (edits in the past, undo, prolonging, reading backwards, reading states) the cursor gives
 * exactly what a fresh replay gives.
 */
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { TimelineCore } from "./core.js";
import { LogCursor } from "./logCursor.js";
import { Timeline } from "./timeline.js";
import type { LogEvent } from "./types.js";

/** A gas of 40 discs, 5,000 events: several keyframes, and action records at t = 0. */
function gas(): Timeline {
  const tl = Timeline.fromScene(dilutedGas({ n: 40, packing: 0.2, seed: 3 }));
  tl.prolong({ events: 5000 });
  return tl;
}

/** The whole log read by a timeline that never read before (a fresh replay from each keyframe). */
function freshLog(tl: Timeline): LogEvent[] {
  const copy = Timeline.fromScene(tl.toScene());
  copy.prolongTo(tl.horizon);
  return copy.eventRange(0, tl.eventCount);
}

function coreOf(tl: Timeline): TimelineCore {
  return (tl as unknown as { core: TimelineCore }).core;
}

describe("LogCursor", () => {
  it("a walk by event(i) gives the log a fresh replay gives, and replays each record once", () => {
    const tl = gas();
    const n = tl.eventCount;
    const core = coreOf(tl);
    const cursor = new LogCursor();
    const walked: LogEvent[] = [];
    for (let i = 0; i < n; i++) walked.push(...cursor.read(core, i, i + 1));
    expect(walked).toEqual(freshLog(tl));
    expect(cursor.replayed).toBe(n);
  });

  it("a read that starts before the cursor, or past the next keyframe, starts again from a keyframe", () => {
    const tl = gas();
    const core = coreOf(tl);
    const cursor = new LogCursor();
    const all = freshLog(tl);
    expect(cursor.read(core, 3000, 3010)).toEqual(all.slice(3000, 3010));
    const afterFirst = cursor.replayed;
    expect(afterFirst).toBeLessThanOrEqual(3010); // from the keyframe before 3000, not from 0
    expect(cursor.read(core, 100, 101)).toEqual(all.slice(100, 101)); // backwards
    expect(cursor.read(core, 4900, 4901)).toEqual(all.slice(4900, 4901)); // far ahead
    expect(cursor.replayed - afterFirst).toBeLessThan(4901 - 101); // not replayed through
  });

  it("an edit in the past between two reads is seen: the walk goes on over the recomputed log", () => {
    const tl = gas();
    const t = tl.event(2000).time;
    for (let i = 0; i < 2100; i++) tl.event(i); // the cursor now stands at record 2100
    tl.apply({ time: t, type: "giveVelocity", id: "d7", v: [3, -2] });
    tl.prolong({ events: 1000 });
    const walked: LogEvent[] = [];
    for (let i = 2100; i < tl.eventCount; i++) walked.push(tl.event(i));
    expect(walked).toEqual(freshLog(tl).slice(2100));
  });

  it("an undo (setActions) and prolonging between reads are seen", () => {
    const tl = gas();
    const before = tl.actions;
    tl.apply({ time: tl.event(1500).time, type: "removeBody", id: "d3" });
    tl.prolong({ events: 500 });
    for (let i = 1400; i < 1600; i++) tl.event(i);
    tl.setActions(before);
    tl.prolong({ events: 300 });
    const fresh = freshLog(tl);
    for (let i = 1600; i < 1700; i++) expect(tl.event(i)).toEqual(fresh[i]);
    const n = tl.eventCount;
    tl.prolong({ events: 200 }); // appends: the cursor may go on
    expect(tl.eventRange(n - 5, Number.POSITIVE_INFINITY)).toEqual(freshLog(tl).slice(n - 5));
  });

  it("reading states between log reads changes nothing (the cursor has its own motions)", () => {
    const tl = gas();
    const all = freshLog(tl);
    for (let i = 1000; i < 1200; i++) {
      expect(tl.event(i)).toEqual(all[i]);
      tl.stateAt((all[(i * 7) % all.length] as LogEvent).time);
    }
    expect(tl.eventsBetween((all[1200] as LogEvent).time, (all[1210] as LogEvent).time)).toEqual(
      all.filter((e) => e.time >= (all[1200] as LogEvent).time && e.time <= (all[1210] as LogEvent).time),
    );
  });
});
