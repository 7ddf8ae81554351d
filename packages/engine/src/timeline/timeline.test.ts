import { describe, expect, it } from "vitest";
import { dilutedGas, galperin, newtonsCradle, originalDemo } from "../scene/presets.js";
import type { Action, SceneFile } from "../scene/types.js";
import { SimulationError } from "../sim/errors.js";
import type { WorldEvent } from "../sim/types.js";
import { World } from "../sim/world.js";
import { applyToWorld } from "./applyAction.js";
import { CONVERGING_PAIR, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** Runs a scene whose actions are all at t = 0 directly on a World, copying every event. */
function worldRun(s: SceneFile, untilTime: number): { world: World; events: WorldEvent[] } {
  const w = new World({ g: s.g, gravity: s.gravity });
  for (const a of s.actions) applyToWorld(w, a, "a");
  const events: WorldEvent[] = [];
  w.advance({ untilTime }, (e) => events.push({ ...e }));
  return { world: w, events };
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

describe("prolong's reason", () => {
  // "idle" means no event is left; an action still scheduled later is one (review 7: the CLI's
  // `simulate --until-time 2` printed the state at t = 0 for a scene with a body added at t = 5)
  const later: Action[] = [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
    { time: 5, type: "addBody", id: "b", x: 20, y: 0, r: 1, m: 1, v: [-1, 0] },
  ];

  it("is 'time', not 'idle', when the time limit comes before a scheduled action", () => {
    const tl = Timeline.fromScene(scene(later, 0), { compute: false });
    expect(tl.prolong({ time: 2 })).toEqual({ events: 0, reason: "time" });
    expect(tl.prolongSlice({ time: 1 }, 10)).toEqual({ done: true, events: 0, horizon: 3, reason: "time" });
  });

  it("is 'idle' at the time limit once every action is applied and nothing is queued", () => {
    const tl = Timeline.fromScene(scene(later, 0), { compute: false });
    expect(tl.prolong({ time: 20 })).toEqual({ events: 1, reason: "idle" });
    expect(tl.horizon).toBe(20);
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
    const s = scene([...CONVERGING_PAIR], 0.5);
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
