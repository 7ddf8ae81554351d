import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import { parseScene } from "../scene/parse.js";
import { dilutedGas, galperin, newtonsCradle, originalDemo } from "../scene/presets.js";
import type { Action, SceneFile } from "../scene/types.js";
import { SimulationError } from "../sim/errors.js";
import type { WorldEvent } from "../sim/types.js";
import { World } from "../sim/world.js";
import { applyToWorld } from "./applyAction.js";
import { Timeline } from "./timeline.js";

const scene = (actions: Action[], g = 9.81): SceneFile => ({
  format: "chapgame",
  version: 1,
  g,
  gravity: [0, 0],
  actions,
});
const disc = (id: string, x: number, y: number, v: [number, number] = [0, 0], time = 0): Action => ({
  time,
  type: "addBody",
  id,
  x,
  y,
  r: 1,
  m: 1,
  mu: 0,
  v,
});

/** Runs a scene whose actions are all at t = 0 directly on a World, copying every event. */
function worldRun(s: SceneFile, untilTime: number): { world: World; events: WorldEvent[] } {
  const w = new World({ g: s.g, gravity: s.gravity });
  for (const a of s.actions) applyToWorld(w, a, "a");
  const events: WorldEvent[] = [];
  w.advance({ untilTime }, (e) => events.push({ ...e }));
  return { world: w, events };
}

/** Everything observable about a timeline, for "nothing changed" checks. */
function fingerprint(tl: Timeline): unknown {
  const times = [0, tl.horizon / 3, tl.horizon / 2, tl.horizon];
  return {
    scene: tl.toScene(),
    horizon: tl.horizon,
    counts: tl.counts(),
    log: tl.eventsBetween(0, tl.horizon),
    states: times.map((t) => tl.stateAt(t)),
    bytes: tl.historyBytes(),
  };
}

describe("Timeline on the reference cases", () => {
  it("the original's sample: one collision at 100 − √9700, then A slides left and B rests at 550", () => {
    const tl = Timeline.fromScene(originalDemo());
    tl.prolong({});
    const hits = tl.eventsBetween(0, tl.horizon).filter((e) => e.type === "bodyBody");
    expect(hits).toHaveLength(1);
    const t = hits[0]?.time as number;
    expect(Math.abs(t - 1.5114219820389536)).toBeLessThan(1e-14);
    const after = tl.stateAt(t);
    expect(after.bodies.map((b) => b.id)).toEqual(["A", "B"]);
    expect(after.bodies[0]?.vx).toBeCloseTo(-98.4886, 3);
    expect(after.bodies[1]?.vx).toBe(0);
    expect(after.bodies[1]?.x).toBeCloseTo(550, 9);
  });

  it("Newton's cradle: only the last disc leaves, at (4, 0)", () => {
    const tl = Timeline.fromScene(newtonsCradle());
    tl.prolong({ time: 10 });
    const v = tl.stateAt(10).bodies.map((b) => [b.id, b.vx, b.vy]);
    expect(v).toEqual([
      ["c1", 0, 0],
      ["c2", 0, 0],
      ["c3", 0, 0],
      ["c4", 0, 0],
      ["c5", 4, 0],
      ["striker", 0, 0],
    ]);
  });

  it("friction stop: decelerates at 5 along (0.6, 0.8) and stops at t = 1 at (1.5, 2)", () => {
    const tl = Timeline.fromScene(
      scene([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0.5, v: [3, 4] }], 10),
    );
    tl.prolong({});
    const half = tl.stateAt(0.5).bodies[0];
    expect([half?.x, half?.y, half?.vx, half?.vy]).toEqual([1.125, 1.5, 1.5, 2]);
    expect(tl.eventsBetween(0, 2).filter((e) => e.type === "stop")).toEqual([
      { time: 1, type: "stop", ids: ["a"], point: [1.5, 2], normal: null, impulse: 0 },
    ]);
    const later = tl.stateAt(tl.horizon).bodies[0];
    expect([later?.x, later?.y, later?.vx, later?.vy]).toEqual([1.5, 2, 0, 0]);
  });

  it("Galperin's billiard counts the digits of π for n = 1…5", () => {
    const digits = [3, 31, 314, 3141, 31415];
    for (let n = 1; n <= 5; n++) {
      const tl = Timeline.fromScene(galperin(n));
      const res = tl.prolong({});
      expect(res.reason).toBe("idle");
      const c = tl.counts();
      expect(c.bodyBody + c.bodyLine).toBe(digits[n - 1]);
    }
  });
});

describe("Timeline agrees with the World", () => {
  const gas = dilutedGas({ n: 60, packing: 0.2, seed: 3 });

  it("stateAt(t) equals World.bodies(t) bit for bit", () => {
    const tl = Timeline.fromScene(gas);
    for (const T of [0.5, 3, 7.25]) {
      tl.prolongTo(T);
      const { world } = worldRun(gas, T);
      expect(tl.stateAt(T).bodies).toStrictEqual(world.bodies(T));
    }
  });

  it("the log has the World's events: times, kinds, ids, contact points, normals and impulses", () => {
    const tl = Timeline.fromScene(gas);
    tl.prolongTo(6);
    const { events } = worldRun(gas, 6);
    const log = tl.eventsBetween(0, 6).filter((e) => e.type !== "action");
    expect(log.length).toBe(events.length);
    expect(log.length).toBeGreaterThan(50);
    log.forEach((l, i) => {
      const e = events[i] as WorldEvent;
      expect(l.time).toBe(e.time);
      expect(l.type).toBe(e.kind);
      expect(l.ids).toEqual(e.b === null ? [e.a] : [e.a, e.b]);
      expect(l.point).toEqual([e.px, e.py]);
      expect(l.normal).toEqual(e.kind === "stop" ? null : [e.nx, e.ny]);
      expect(l.impulse).toBe(e.impulse);
    });
  });

  it("event(i) equals eventsBetween, and next/prev event times step through the log", () => {
    const tl = Timeline.fromScene(gas);
    tl.prolong({ events: 300 });
    const all = tl.eventsBetween(0, tl.horizon);
    expect(all.length).toBe(tl.eventCount);
    for (const i of [0, 1, 59, 60, 61, 200, all.length - 1]) expect(tl.event(i)).toEqual(all[i]);
    let t = 0;
    const distinct = [...new Set(all.map((e) => e.time))];
    const stepped = [0];
    for (let n = tl.nextEventTime(t); n !== null; n = tl.nextEventTime(t)) {
      stepped.push(n);
      t = n;
    }
    expect(stepped).toEqual(distinct[0] === 0 ? distinct : [0, ...distinct]);
    expect(tl.prevEventTime(t)).toBe(stepped[stepped.length - 2]);
    expect(tl.prevEventTime(0)).toBeNull();
    expect(() => tl.event(all.length)).toThrow(RangeError);
  });
});

describe("a scene the exact model cannot continue (Zeno)", () => {
  it("a frictionless disc pushing a braking one: prolong throws, the history before it stays readable", () => {
    // found by the slices property (seed 7): collisions and stops converge geometrically to t ≈ 52.249
    const s = scene(
      [
        { time: 0, type: "addBody", id: "b0", x: 3, y: 3, r: 0.3, m: 0.7401641156608975, mu: 0, v: [0.1, 0] },
        { time: 0, type: "addBody", id: "b1", x: 7, y: 3, r: 0.3, m: 0.5, mu: 0.05 },
      ],
      0.5,
    );
    const tl = Timeline.fromScene(s);
    expect(() => tl.prolong({ time: 60 })).toThrow(SimulationError);
    expect(tl.horizon).toBeCloseTo(52.24895312777856, 9);
    expect(tl.counts().stop).toBeGreaterThan(60);
    const at40 = tl.stateAt(40).bodies;
    const bare = Timeline.fromScene(s);
    bare.prolongTo(40);
    expect(bare.stateAt(40).bodies).toStrictEqual(at40);
  });
});

describe("an edit that drives the scene into a Zeno state is refused and changes nothing", () => {
  it("an immovable disc given a velocity that crushes a disc against the wall", () => {
    // found by the "past" property (seed 15429542, shrunk by hand): apply() recomputes the future,
    // the World reports the crush as a SimulationError, and the timeline keeps its former history.
    const box: Action[] = [
      { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
      { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 20], kind: "segment" },
      { time: 0, type: "addLine", id: "n", p1: [20, 20], p2: [0, 20], kind: "segment" },
      { time: 0, type: "addLine", id: "w", p1: [0, 20], p2: [0, 0], kind: "segment" },
      { time: 0, type: "addBody", id: "b0", x: 3, y: 3, r: 0.3, m: 0.5, mu: 0, v: [-0.1, 0] },
      { time: 0, type: "addBody", id: "b1", x: 7, y: 3, r: 0.3, m: Number.POSITIVE_INFINITY, mu: 0 },
    ];
    const tl = Timeline.fromScene(scene(box, 0.5));
    tl.prolongTo(1.35);
    const before = { horizon: tl.horizon, log: tl.eventsBetween(0, 1.35), at1: tl.stateAt(1) };
    expect(() => tl.apply({ time: 1e-9, type: "giveVelocity", id: "b1", v: [-5, 0] })).toThrow(
      SimulationError,
    );
    expect(tl.actions).toHaveLength(box.length);
    expect({ horizon: tl.horizon, log: tl.eventsBetween(0, 1.35), at1: tl.stateAt(1) }).toStrictEqual(before);
  });
});

describe("history storage", () => {
  it("stays under 64 bytes per recorded event (Galperin, 314,159 events)", () => {
    const tl = Timeline.fromScene(galperin(6));
    tl.prolong({});
    expect(tl.eventCount).toBeGreaterThan(314_159);
    expect(tl.historyBytes() / tl.eventCount).toBeLessThan(64);
  });

  it("stays under 64 bytes per recorded event (1,000-disc gas, 100,000 events)", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 1000, packing: 0.1, seed: 1 }));
    tl.prolong({ events: 100_000 });
    expect(tl.historyBytes() / tl.eventCount).toBeLessThan(64);
  });

  it("adding bodies one apply() at a time at t = 0 stores what fromScene stores, and the same history", () => {
    const s = dilutedGas({ n: 300, packing: 0.1, seed: 2 });
    const whole = Timeline.fromScene(s);
    const oneByOne = new Timeline({ g: s.g });
    for (const a of s.actions) oneByOne.apply(a);
    expect(oneByOne.historyBytes()).toBe(whole.historyBytes());
    whole.prolongTo(5);
    oneByOne.prolongTo(5);
    expect(oneByOne.eventsBetween(0, 5)).toEqual(whole.eventsBetween(0, 5));
    expect(oneByOne.stateAt(5)).toEqual(whole.stateAt(5));
  });

  it("history: false keeps no log, gives the same state at the horizon, and refuses the past", () => {
    const s = dilutedGas({ n: 40, packing: 0.2, seed: 5 });
    const full = Timeline.fromScene(s);
    const bare = Timeline.fromScene(s, { history: false });
    full.prolong({ events: 500 });
    bare.prolong({ events: 500 });
    expect(bare.horizon).toBe(full.horizon);
    expect(bare.counts()).toEqual(full.counts());
    expect(bare.stateAt(bare.horizon).bodies).toStrictEqual(full.stateAt(full.horizon).bodies);
    expect(bare.eventCount).toBe(0);
    expect(bare.historyBytes()).toBe(0);
    expect(() => bare.stateAt(bare.lastLoggedTime() / 2)).toThrow(RangeError);
    expect(() => bare.apply({ time: bare.horizon / 2, type: "removeBody", id: "d0" })).toThrow(
      "action.time: must be >= the horizon",
    );
  });
});

describe("actions and their validation against the simulated state", () => {
  const moving = () => Timeline.fromScene(scene([disc("a", 0, 0, [1, 0]), disc("far", 100, 100)]));

  it("refuses a body added where another has moved to (overlap at t > 0), and changes nothing", () => {
    const tl = moving();
    tl.prolongTo(10);
    const before = fingerprint(tl);
    const rev = tl.getSnapshot();
    // at t = 5 body a is at (5, 0)
    expect(() => tl.apply(disc("b", 5.5, 0, [0, 0], 5))).toThrow(
      'action: body "b" would overlap body "a" at time 5',
    );
    expect(() => tl.apply(disc("b", 15.5, 0, [0, 0], 15))).toThrow(
      'action: body "b" would overlap body "a" at time 15',
    );
    expect(fingerprint(tl)).toEqual(before);
    expect(tl.getSnapshot()).toBe(rev);
    tl.apply(disc("b", 5.5, 0, [0, 0], 1)); // at t = 1, a is at (1, 0): fine
    expect(tl.getSnapshot()).not.toBe(rev);
  });

  it("refuses growing into an overlap, a line across a moving body, actions on ids gone at that time", () => {
    const tl = moving();
    tl.prolongTo(10);
    tl.apply({ time: 6, type: "removeBody", id: "far" });
    const before = fingerprint(tl);
    const refusals: [Action, string][] = [
      [
        { time: 4, type: "updateBody", id: "far", r: 200 },
        'action: body "far" would overlap body "a" at time 4',
      ],
      [
        { time: 3, type: "addLine", id: "w", p1: [3, -5], p2: [3, 5], kind: "segment" },
        'action: line "w" would overlap body "a" at time 3',
      ],
      [
        { time: 3, type: "addPoint", id: "p", p: [3.5, 0] },
        'action: point "p" would overlap body "a" at time 3',
      ],
      [{ time: 7, type: "giveVelocity", id: "far", v: [1, 1] }, 'action.id: no body "far" at time 7'],
      [
        { time: 5, type: "addBody", id: "a", x: 50, y: 50, r: 1, m: 1 },
        'action.id: body "a" already exists at time 5',
      ],
      [{ time: -1, type: "removeBody", id: "a" }, "action.time: must be a non-negative finite number"],
    ];
    for (const [a, msg] of refusals) {
      expect(() => tl.apply(a)).toThrow(SceneError);
      expect(() => tl.apply(a)).toThrow(msg);
      expect(fingerprint(tl)).toEqual(before);
    }
  });

  it("refuses an action in the past that makes a later action invalid, and changes nothing", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0), disc("b", 10, 0, [0, 0], 5)]));
    tl.prolongTo(8);
    const before = fingerprint(tl);
    // sending a towards x = 10 puts it where b is added at t = 5; the later action is named by its
    // index in tl.actions (it was its index in the list with the refused action inserted: actions[2])
    expect(() => tl.apply({ time: 1, type: "giveVelocity", id: "a", v: [2.5, 0] })).toThrow(
      'actions[1]: body "b" would overlap body "a" at time 5 (once this action is in place)',
    );
    expect(tl.actions[1]).toMatchObject({ type: "addBody", id: "b" });
    expect(() => tl.apply({ time: 0.5, type: "removeBody", id: "b" })).toThrow('action.id: no body "b"');
    expect(fingerprint(tl)).toEqual(before);
    tl.apply({ time: 6, type: "giveVelocity", id: "b", v: [1, 0] });
    expect(() => tl.apply({ time: 5.5, type: "removeBody", id: "b" })).toThrow(
      'actions[2].id: no body "b" at time 6 (once this action is in place)',
    );
    expect(tl.actions[2]).toMatchObject({ type: "giveVelocity", id: "b" });
  });

  it("fromScene refuses what parseScene cannot see: an overlap with a body that moved", () => {
    const s = scene([disc("a", 0, 0, [1, 0]), disc("b", 4.5, 0, [0, 0], 3)]);
    expect(() => parseScene(s)).not.toThrow();
    expect(() => Timeline.fromScene(s)).toThrow('actions[1]: body "b" would overlap body "a" at time 3');
  });

  it("setActions is atomic: an invalid list leaves the timeline as it was", () => {
    const tl = moving();
    tl.prolongTo(5);
    const before = fingerprint(tl);
    expect(() => tl.setActions([disc("a", 0, 0), disc("b", 1, 0)])).toThrow(
      'actions[1]: body "b" would overlap body "a" at time 0',
    );
    expect(() => tl.setActions([disc("a", 0, 0), { time: 1, type: "removeBody", id: "x" }])).toThrow(
      'actions[1].id: no body "x" at time 1',
    );
    expect(fingerprint(tl)).toEqual(before);
  });

  it("undo/redo by setActions in a long history restarts from a World keyframe and equals from scratch", () => {
    const s = dilutedGas({ n: 100, packing: 0.2, seed: 4 });
    const tl = Timeline.fromScene(s);
    tl.prolong({ events: 40_000 });
    const H = tl.horizon;
    const late: Action = { time: 0.9 * H, type: "giveVelocity", id: "d7", v: [0.5, 0.5] };
    tl.apply(late);
    const withLate = Timeline.fromScene({ ...s, actions: [...s.actions, late] });
    withLate.prolongTo(H);
    expect(tl.eventsBetween(0.85 * H, H)).toEqual(withLate.eventsBetween(0.85 * H, H));
    tl.setActions(s.actions);
    const original = Timeline.fromScene(s);
    original.prolongTo(H);
    expect(tl.eventsBetween(0.85 * H, H)).toEqual(original.eventsBetween(0.85 * H, H));
    expect(tl.stateAt(H)).toEqual(original.stateAt(H));
    expect(tl.counts()).toEqual(original.counts());
  });

  it("events an action causes at its own time are part of the state at that time (touching cradle at t = 0)", () => {
    const s = newtonsCradle();
    const striker = s.actions.find((a) => a.type === "addBody" && a.id === "striker");
    if (striker?.type === "addBody") striker.x = -2; // touching c1, moving towards it
    const tl = Timeline.fromScene(s);
    tl.prolongTo(0);
    expect(tl.stateAt(0).bodies.map((b) => b.vx)).toEqual([0, 0, 0, 0, 4, 0]);
    expect(tl.counts().bodyBody).toBe(5);
    // the same actions one apply() at a time, and one more at t = 0 afterwards (recomputed)
    const one = new Timeline({ g: s.g });
    for (const a of s.actions) one.apply(a);
    expect(one.eventsBetween(0, 0)).toEqual(tl.eventsBetween(0, 0));
    const extra: Action = { time: 0, type: "addPoint", id: "p", p: [50, 50] };
    one.apply(extra);
    const scratch = Timeline.fromScene({ ...s, actions: [...s.actions, extra] });
    scratch.prolongTo(0);
    expect(one.eventsBetween(0, 0)).toEqual(scratch.eventsBetween(0, 0));
    expect(one.stateAt(0)).toEqual(scratch.stateAt(0));
  });

  it("an action's until computes that far ahead: seconds, events, or until idle", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0), disc("b", 10, 0)]));
    expect(tl.horizon).toBe(0);
    tl.apply({ time: 1, type: "giveVelocity", id: "a", v: [1, 0], until: { time: 2.5 } });
    expect(tl.horizon).toBe(3.5);
    tl.apply({ time: 4, type: "giveVelocity", id: "b", v: [-1, 0], until: { events: 1 } });
    expect(tl.counts().bodyBody).toBe(1);
    expect(tl.horizon).toBeCloseTo(4 + (10 - 3 - 2) / 2, 12); // at t = 4: a at 3, b at 10, closing at 2
    tl.apply({ time: tl.horizon, type: "setGlobal", g: 1, until: {} });
    expect(tl.counts().bodyBody).toBe(1);
  });

  it("subscribe is called after every change, getSnapshot changes with it, unsubscribe stops it", () => {
    const tl = moving();
    let calls = 0;
    const off = tl.subscribe(() => calls++);
    const r0 = tl.getSnapshot();
    tl.prolong({ time: 1 });
    tl.apply(disc("c", 50, 0, [0, 0], 0.5));
    tl.setActions(tl.actions);
    expect(calls).toBe(3);
    expect(tl.getSnapshot()).toBe(r0 + 3);
    off();
    tl.prolong({ time: 1 });
    expect(calls).toBe(3);
  });

  it("toScene round-trips: the same actions and the same history", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.2, seed: 9 }));
    tl.apply({ time: 2, type: "giveVelocity", id: "d3", v: [3, -1] });
    tl.apply({ time: 1, type: "setGlobal", g: 2 });
    tl.prolongTo(6);
    const back = Timeline.fromScene(tl.toScene());
    back.prolongTo(6);
    expect(back.toScene()).toEqual(tl.toScene());
    expect(back.eventsBetween(0, 6)).toEqual(tl.eventsBetween(0, 6));
    expect(back.stateAt(6)).toEqual(tl.stateAt(6));
  });
});
