/**
 * Timeline.forgetBefore (forget.ts, kept.ts): the start of a history dropped (its memory: forgetMemory.test.ts),
 * and everything from the kept start on read and edited exactly as on a twin that never forgot.
 */
import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import { dilutedGas } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { coreOf, disc, expectSameKept, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const BOX: Action[] = [
  { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
  { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 20], kind: "segment" },
  { time: 0, type: "addLine", id: "n", p1: [20, 20], p2: [0, 20], kind: "segment" },
  { time: 0, type: "addLine", id: "w", p1: [0, 20], p2: [0, 0], kind: "segment" },
];

/** Six discs in a box, kicked at t = 2, 4 (two at once), 6 and 8; computed up to 12. */
function boxScene(): Action[] {
  return [
    ...BOX,
    disc("a", 3, 3, [2, 1]),
    disc("b", 8, 3, [-1, 2]),
    disc("c", 13, 3, [1, -1.5]),
    disc("d", 3, 10, [0.5, 2]),
    disc("e", 10, 10, [-2, -1]),
    disc("f", 16, 16, [1.5, 0.5]),
    { time: 2, type: "giveVelocity", id: "a", v: [-1, 3] },
    { time: 4, type: "giveVelocity", id: "b", v: [2, 2] },
    { time: 4, type: "giveVelocity", id: "c", v: [-3, 1] },
    { time: 6, type: "giveVelocity", id: "d", v: [1, -2] },
    { time: 8, type: "giveVelocity", id: "e", v: [3, 0.5] },
  ];
}

function box(): Timeline {
  const tl = Timeline.fromScene(scene(boxScene(), 0));
  tl.prolongTo(12);
  return tl;
}

/** What a timeline shows from its kept start on, for "nothing changed" checks. */
function keptFingerprint(tl: Timeline): unknown {
  const s = tl.historyStart;
  return {
    snapshot: tl.getSnapshot(),
    start: [s, tl.firstEvent, tl.eventCount, tl.horizon, tl.counts(), tl.toScene()],
    log: tl.eventRange(tl.firstEvent, Number.POSITIVE_INFINITY),
    states: [s, (s + tl.horizon) / 2, tl.horizon].map((t) => tl.stateAt(t)),
    bytes: tl.historyBytes(),
  };
}

function sceneError(f: () => void): SceneError {
  try {
    f();
  } catch (e) {
    if (e instanceof SceneError) return e;
    throw e;
  }
  throw new Error("no SceneError");
}

describe("Timeline.forgetBefore", () => {
  it("cuts at the last keyframe at or before t, keeps entry numbers and reads exactly as before", () => {
    const tl = box();
    const twin = box();
    expect([tl.historyStart, tl.firstEvent]).toEqual([0, 0]);
    expect(tl.forgetBefore(5)).toBe(4); // the keyframe after the actions at 4
    expect(tl.historyStart).toBe(4);
    // the log starts right after the two actions at 4
    const first = tl.firstEvent;
    expect(twin.eventRange(first - 2, first).map((e) => [e.time, e.type])).toEqual([
      [4, "action"],
      [4, "action"],
    ]);
    expect(tl.event(first)).toStrictEqual(twin.event(first));
    expect(tl.eventAction(first)).toBe(twin.eventAction(first));
    expectSameKept(tl, twin, [4.5, 6, 7.25, 8, 11]);
    // a second cut further on, and one before the start (nothing more to forget)
    expect(tl.forgetBefore(9)).toBe(8);
    expect(tl.forgetBefore(3)).toBe(8);
    expectSameKept(tl, twin, [8.5, 10]);
  });

  it("refuses reads before the start with a RangeError naming it; prevEventTime answers null", () => {
    const tl = box();
    tl.forgetBefore(5);
    const first = tl.firstEvent;
    expect(() => tl.event(0)).toThrow(
      new RangeError(
        `event(index): must be at least ${first}, the first entry kept (got 0): event 0 was forgotten (forgetBefore), the log starts at entry ${first} (t = 4): to keep it, call forgetBefore with an earlier time, or not at all`,
      ),
    );
    expect(() => tl.event(first - 1)).toThrow(RangeError);
    expect(() => tl.eventAction(0)).toThrow(
      /^eventAction\(index\): must be at least \d+, the first entry kept \(got 0\): event 0 was forgotten/,
    );
    expect(() => tl.eventRange(0, 10)).toThrow(
      /^eventRange\(index\): must be at least \d+, the first entry kept \(got 0\): event 0 was forgotten/,
    );
    // the time asked, the earliest readable time and how to keep the history
    expect(() => tl.stateAt(3.9)).toThrow(
      new RangeError(
        `stateAt(t): must be a number in [4, 12] (got 3.9): the history before 4 was forgotten (forgetBefore), so the earliest readable time is 4 (the log starts at entry ${first} (t = 4)): to keep it, call forgetBefore with an earlier time, or not at all`,
      ),
    );
    expect(() => tl.nextEventTime(3)).toThrow(
      /^nextEventTime\(t\): must be >= 4 \(got 3\): the history before 4 was forgotten \(forgetBefore\), so the earliest readable time is 4 .*: to keep it, call forgetBefore with an earlier time, or not at all$/,
    );
    expect(() => tl.nextEventTime(Number.NEGATIVE_INFINITY)).toThrow(RangeError);
    expect(() => tl.eventsBetween(0, 12)).toThrow(/^eventsBetween\(t0\): must be >= 4 \(got 0\)/);
    expect(tl.prevEventTime(3)).toBeNull();
    expect(tl.prevEventTime(4)).toBeNull();
    expect(tl.eventRange(first, first + 1)).toHaveLength(1);
    // bad indices and times are still told as before
    expect(() => tl.event(tl.eventCount)).toThrow(/^event\(index\): must be an integer in \[0, /);
    expect(() => tl.stateAt(Number.NaN)).toThrow(RangeError);
  });

  it("refuses edits before the start with a SceneError and changes nothing", () => {
    const tl = box();
    tl.forgetBefore(5);
    const before = keptFingerprint(tl);
    const e = sceneError(() => tl.apply({ time: 3, type: "giveVelocity", id: "a", v: [1, 1] }));
    expect([e.path, e.reason]).toEqual([
      "action.time",
      "must be at or after 4: the history before it was forgotten (forgetBefore)",
    ]);
    const list = tl.toScene().actions;
    const changed = list.map((a) => (a.time === 2 ? { ...a, v: [5, 5] as [number, number] } : a));
    expect(sceneError(() => tl.setActions(changed)).path).toBe(
      `actions[${list.findIndex((a) => a.time === 2)}].time`,
    );
    const removed = list.filter((a) => a.time !== 2);
    const r = sceneError(() => tl.setActions(removed));
    expect([r.path, r.reason]).toEqual([
      "actions",
      "must keep the action at 2 (giveVelocity): edits must be at or after 4: the history before it was forgotten (forgetBefore)",
    ]);
    // an action of the group at 4 is in the first kept keyframe: changing it is refused too
    const atStart = list.map((a) =>
      a.time === 4 && a.type === "giveVelocity" && a.id === "b" ? { ...a, v: [1, 0] as [number, number] } : a,
    );
    expect(sceneError(() => tl.setActions(atStart)).reason).toMatch(
      /^must be after 4: the history was forgotten up to there/,
    );
    expect(keptFingerprint(tl)).toStrictEqual(before);
  });

  it("edits at and after the start equal a timeline that never forgot, bit for bit", () => {
    const tl = box();
    const twin = box();
    tl.forgetBefore(5);
    const edits: Action[] = [
      { time: 4, type: "giveVelocity", id: "f", v: [-1, -1] }, // joins the group at the start
      { time: 5.5, type: "giveVelocity", id: "a", v: [2, -2] },
      { time: 9, type: "removeBody", id: "c" },
    ];
    for (const a of edits) {
      tl.apply(a);
      twin.apply(a);
      expectSameKept(tl, twin, [4, 5, 5.5, 7, 9, 10]);
    }
    // setActions: change an action after the start, add one at the start, then undo
    const list = tl.toScene().actions;
    const next = [
      ...list.map((a) => (a.time === 6 ? { ...a, v: [0, 3] as [number, number] } : a)),
      edits[0] as Action,
    ];
    tl.setActions(next);
    twin.setActions(next);
    expectSameKept(tl, twin, [4, 6, 8, 11]);
    tl.setActions(list);
    twin.setActions(list);
    expectSameKept(tl, twin, [4, 6, 8, 11]);
    expect(tl.historyStart).toBe(4); // restarted from the kept start, not rebuilt from scratch
    expect(coreOf(tl).records.length).toBe(tl.eventCount - tl.firstEvent);
    tl.prolongTo(15);
    twin.prolongTo(15);
    expectSameKept(tl, twin, [12, 14]);
    expect(tl.lastLoggedTime()).toBe(twin.lastLoggedTime());
  });

  it("compute: false: setActions stays at the kept keyframe it restarts from, as the twin does", () => {
    const make = () => {
      const t = Timeline.fromScene(scene(boxScene(), 0), { compute: false });
      t.prolongTo(12);
      return t;
    };
    const tl = make();
    const twin = make();
    expect(tl.forgetBefore(5)).toBe(4);
    const list = tl.toScene().actions.map((a) => (a.time === 6 ? { ...a, time: 6.5 } : a));
    tl.setActions(list);
    twin.setActions(list);
    expect([tl.horizon, tl.lastLoggedTime()]).toEqual([4, twin.lastLoggedTime()]);
    expect(twin.horizon).toBe(4);
    tl.prolongTo(12);
    twin.prolongTo(12);
    expectSameKept(tl, twin, [5, 6.5, 9]);
  });

  it("restarts from a keyframe taken between actions (periodic) as from any other", () => {
    const gas = dilutedGas({ n: 60, packing: 0.15, seed: 7 });
    const make = () => {
      const t = Timeline.fromScene(gas);
      t.prolong({ events: 5000 });
      return t;
    };
    const tl = make();
    const twin = make();
    const periodic = coreOf(tl).keyframes.filter((k) => !k.afterActions && k.time > 0);
    expect(periodic.length).toBeGreaterThanOrEqual(3);
    const T = (periodic[1] as { time: number }).time;
    expect(tl.forgetBefore(T)).toBe(T);
    expect(coreOf(tl).keyframes[0]?.afterActions).toBe(false);
    expectSameKept(tl, twin, [T + (tl.horizon - T) / 3]);
    // an action at exactly the start: the events of that instant first, then the action
    const id = tl.stateAt(T).bodies[0]?.id as string;
    const a: Action = { time: T, type: "giveVelocity", id, v: [0.5, -0.5] };
    tl.apply(a);
    twin.apply(a);
    expectSameKept(tl, twin, [(T + tl.horizon) / 2]);
  });

  it("a prolongSlice under way goes on across a forgetBefore, as without it", () => {
    const gas = dilutedGas({ n: 40, packing: 0.15, seed: 11 });
    const tl = Timeline.fromScene(gas);
    const twin = Timeline.fromScene(gas);
    twin.prolong({ events: 6000 });
    let slices = 0;
    while (!tl.prolongSlice({ events: 6000 }, 700).done) {
      tl.forgetBefore(tl.horizon);
      slices++;
    }
    expect(slices).toBeGreaterThan(5);
    expect(tl.firstEvent).toBeGreaterThan(4000);
    expectSameKept(tl, twin);
  });

  it("checks t: a number in [0, horizon]; before the kept start it changes nothing", () => {
    const tl = box();
    for (const bad of [Number.NaN, -1, 12.5, Number.POSITIVE_INFINITY, "3", undefined])
      expect(() => tl.forgetBefore(bad as number)).toThrow(
        /^forgetBefore\(t\): must be a number in \[0, 12\], the computed history \(got /,
      );
    expect(tl.firstEvent).toBe(0);
    expect(tl.forgetBefore(12)).toBe(8);
    const before = keptFingerprint(tl);
    expect(tl.forgetBefore(1)).toBe(8);
    expect(keptFingerprint(tl)).toStrictEqual(before);
  });

  it("tells the subscribers when something was dropped, not otherwise", () => {
    const tl = box();
    let calls = 0;
    tl.subscribe(() => calls++);
    const rev = tl.getSnapshot();
    // at 0: the log entries of the actions at 0 go (the keyframe after them starts the history)
    expect(tl.forgetBefore(0)).toBe(0);
    expect([tl.firstEvent, calls]).toEqual([10, 1]);
    expect(tl.getSnapshot()).not.toBe(rev);
    tl.forgetBefore(7);
    expect(calls).toBe(2);
    tl.forgetBefore(7); // nothing more to drop
    tl.forgetBefore(2);
    expect(calls).toBe(2);
  });

  it("without history: nothing to forget, returns the horizon", () => {
    const tl = Timeline.fromScene(scene(boxScene(), 0), { history: false });
    tl.prolongTo(12);
    let calls = 0;
    tl.subscribe(() => calls++);
    expect(tl.forgetBefore(5)).toBe(12);
    expect([tl.historyStart, tl.firstEvent, tl.eventCount, calls]).toEqual([0, 0, 0, 0]);
    expect(tl.stateAt(12).bodies).toHaveLength(6);
  });

  it("a log walk across the cut starts its replay again and reads the same entries", () => {
    const gas = dilutedGas({ n: 40, packing: 0.15, seed: 5 });
    const make = () => {
      const t = Timeline.fromScene(gas);
      t.prolong({ events: 4000 });
      return t;
    };
    const tl = make();
    const twin = make();
    tl.eventRange(0, 10); // the replay stopped before record 10
    tl.forgetBefore(twin.event(Math.floor(twin.eventCount / 2)).time);
    // record 10 is now entry firstEvent + 10: the old position must not be taken for it
    const from = tl.firstEvent;
    expect(from).toBeGreaterThan(1000);
    for (let i = from + 10; i < from + 300; i++) expect(tl.event(i)).toStrictEqual(twin.event(i));
  });
});
