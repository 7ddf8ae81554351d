/**
 * Timeline.eventDetail(i): each participating body's exact state just before and just after a log
 * entry. Checked against closed forms (elastic head-on pair, a bounce, a friction stop, a fall under
 * gravity), at one instant with several events (Newton's cradle), for actions, and against stateAt
 * around each event of random frictionless scenes.
 */
import { describe, expect, it } from "vitest";
import { dilutedGas, newtonsCradle } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { disc, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";
import type { EventDetail } from "./types.js";

const v = (d: EventDetail, k: number, when: "before" | "after") => {
  const s = d.bodies[k]?.[when];
  return s ? [s.vx, s.vy] : null;
};

/** Index of the first log entry of type `type`. */
function first(tl: Timeline, type: string): number {
  for (let i = 0; i < tl.eventCount; i++) if (tl.event(i).type === type) return i;
  throw new Error(`no ${type} entry`);
}

describe("Timeline.eventDetail", () => {
  it("a head-on pair: velocities before and after are the elastic formula's, exactly", () => {
    // m1 = 1 at 4 m/s onto m2 = 3 at rest: v1' = (m1 - m2) v1 / (m1 + m2) = -2, v2' = 2 m1 v1 / (m1 + m2) = 2
    const tl = Timeline.fromScene(
      scene(
        [
          { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [4, 0] },
          { time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 3, mu: 0 },
        ],
        0,
      ),
    );
    tl.prolongTo(5);
    const i = first(tl, "bodyBody");
    const d = tl.eventDetail(i);
    expect(d).toMatchObject({ ...tl.event(i), time: 2, ids: ["a", "b"] });
    expect(d.bodies.map((b) => b.id)).toEqual(["a", "b"]);
    expect([v(d, 0, "before"), v(d, 1, "before")]).toEqual([
      [4, 0],
      [0, 0],
    ]);
    expect([v(d, 0, "after"), v(d, 1, "after")]).toEqual([
      [-2, 0],
      [2, 0],
    ]);
    expect(d.bodies[0]?.before).toMatchObject({ x: 8, y: 0 });
    expect(d.bodies[0]?.after).toMatchObject({ x: 8, y: 0 });
    expect(d.bodies[1]?.after).toMatchObject({ x: 10, y: 0, m: 3 });
    // momentum before = after, and the impulse is the change of a's momentum
    expect(d.impulse).toBe(6);
  });

  it("a disc–line bounce: only the body, its normal velocity reversed", () => {
    const tl = Timeline.fromScene(
      scene(
        [
          { time: 0, type: "addLine", id: "wall", p1: [-10, 5], p2: [10, 5], kind: "segment" },
          disc("a", 0, 0, [1, 2]),
        ],
        0,
      ),
    );
    tl.prolongTo(3);
    const d = tl.eventDetail(first(tl, "bodyLine"));
    expect(d).toMatchObject({ time: 2, type: "bodyLine", ids: ["a", "wall"], point: [2, 5] });
    expect(d.normal?.map((c) => c + 0)).toEqual([0, 1]); // the normal's x is -0
    expect(d.bodies.map((b) => b.id)).toEqual(["a"]);
    expect(v(d, 0, "before")).toEqual([1, 2]);
    expect(v(d, 0, "after")).toEqual([1, -2]);
  });

  it("a friction stop: velocity 0 before (the motion ends there) and after, at the stopping point", () => {
    // speed 5, mu g = 0.5 × 10 = 5: stops at t = 1 after 2.5, at (1.5, 2)
    const tl = Timeline.fromScene(
      scene([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0.5, v: [3, 4] }], 10),
    );
    tl.prolongTo(2);
    const d = tl.eventDetail(first(tl, "stop"));
    expect(d).toMatchObject({ time: 1, type: "stop", ids: ["a"], point: [1.5, 2], impulse: 0 });
    expect(v(d, 0, "before")).toEqual([0, 0]);
    expect(v(d, 0, "after")).toEqual([0, 0]);
    expect(d.bodies[0]?.before).toMatchObject({ x: 1.5, y: 2 });
  });

  it("Newton's cradle: the simultaneous collisions each get their own before/after, in a chain", () => {
    const tl = Timeline.fromScene(newtonsCradle());
    tl.prolongTo(2);
    const chain: EventDetail[] = [];
    for (let i = 0; i < tl.eventCount; i++)
      if (tl.event(i).type === "bodyBody") chain.push(tl.eventDetail(i));
    expect(chain.map((d) => d.ids)).toEqual([
      ["c1", "striker"],
      ["c1", "c2"],
      ["c2", "c3"],
      ["c3", "c4"],
      ["c4", "c5"],
    ]);
    expect(new Set(chain.map((d) => d.time)).size).toBe(1);
    const moving = ["striker", "c1", "c2", "c3", "c4"];
    chain.forEach((d, k) => {
      // the one arriving at (4, 0) passes it all on to the one at rest
      const arriving = d.bodies.find((b) => b.id === moving[k]);
      const resting = d.bodies.find((b) => b.id !== moving[k]);
      expect([arriving?.before?.vx, arriving?.after?.vx]).toEqual([4, 0]);
      expect([resting?.before?.vx, resting?.after?.vx]).toEqual([0, 4]);
    });
    // reading in another order (backwards: a fresh replay from the keyframe) gives the same
    const backwards = [...chain].reverse().map((d) => tl.eventDetail(tl.eventsBetween(0, d.time).length - 1));
    expect(backwards[0]).toEqual(chain[chain.length - 1]);
  });

  it("under gravity: velocity before = the motion evaluated at the event time; after = reflected", () => {
    const tl = Timeline.fromScene({
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, -10],
      actions: [
        { time: 0, type: "addLine", id: "floor", p1: [-100, 0], p2: [100, 0], kind: "segment" },
        disc("a", 0, 10, [1, 0]),
      ],
    });
    tl.prolongTo(1.5);
    const d = tl.eventDetail(first(tl, "bodyLine"));
    expect(d.time).toBeCloseTo(Math.sqrt(1.8), 14);
    expect(v(d, 0, "before")).toEqual([1, -10 * d.time]);
    const after = d.bodies[0]?.after;
    expect(after?.vx).toBe(1);
    expect(after?.vy).toBeCloseTo(10 * d.time, 13);
    expect(after).toEqual(tl.stateAt(d.time).bodies[0]);
    expect(d.bodies[0]?.before?.ay).toBe(-10);
  });

  it("actions: the body an action names, before and after its instant's actions; none for obstacles", () => {
    const actions: Action[] = [
      { time: 0, type: "addLine", id: "wall", p1: [50, -10], p2: [50, 10], kind: "segment" },
      disc("a", 0, 0, [1, 0]),
      { time: 2, type: "giveVelocity", id: "a", v: [0, 3] },
      { time: 3, type: "updateBody", id: "a", x: 20 },
      { time: 4, type: "removeBody", id: "a" },
    ];
    const tl = Timeline.fromScene(scene(actions, 0));
    tl.prolongTo(5);
    const at = (type: string) => tl.eventDetail(first(tl, type));
    const entries = Array.from({ length: tl.eventCount }, (_, i) => tl.eventDetail(i));
    expect(entries.map((d) => [d.action, d.bodies.map((b) => b.id)])).toEqual([
      ["addLine", []],
      ["addBody", ["a"]],
      ["giveVelocity", ["a"]],
      ["updateBody", ["a"]],
      ["removeBody", ["a"]],
    ]);
    const [, add, give, update, remove] = entries;
    expect(add?.bodies[0]?.before).toBeNull();
    expect(add?.bodies[0]?.after).toMatchObject({ x: 0, y: 0, vx: 1, vy: 0 });
    expect(give?.bodies[0]?.before).toMatchObject({ x: 2, vx: 1, vy: 0 });
    expect(give?.bodies[0]?.after).toMatchObject({ x: 2, vx: 0, vy: 3 });
    expect(update?.bodies[0]?.before).toMatchObject({ x: 2, y: 3, vy: 3 });
    expect(update?.bodies[0]?.after).toMatchObject({ x: 20, y: 3, vy: 3 });
    expect(remove?.bodies[0]?.before).toMatchObject({ x: 20, y: 6 });
    expect(remove?.bodies[0]?.after).toBeNull();
    expect(at("action").bodies).toEqual([]);
  });

  it("eventIndexAt(t): the index of the first entry at or after t, for an entry found by its time", () => {
    const tl = Timeline.fromScene(newtonsCradle());
    tl.prolongTo(2);
    const t = tl.nextEventTime(0) as number; // the cradle's instant: five collisions
    const i = tl.eventIndexAt(t);
    expect(tl.event(i - 1).time).toBeLessThan(t);
    expect(tl.eventsBetween(t, t)).toEqual([0, 1, 2, 3, 4].map((k) => tl.event(i + k)));
    expect(tl.eventIndexAt(Number.NEGATIVE_INFINITY)).toBe(0);
    expect(tl.eventIndexAt(0)).toBe(0);
    expect(tl.eventIndexAt(Number.POSITIVE_INFINITY)).toBe(tl.eventCount);
    expect(() => tl.eventIndexAt(Number.NaN)).toThrow(RangeError);
  });

  it("refuses a bad index like event(i), naming eventDetail", () => {
    const tl = Timeline.fromScene(newtonsCradle());
    tl.prolongTo(2);
    for (const i of [-1, tl.eventCount, 1.5, Number.NaN, "0"])
      expect(() => tl.eventDetail(i as number)).toThrow(
        new RangeError(
          `eventDetail(index): must be an integer in [0, ${tl.eventCount}) (got ${typeof i === "string" ? `the string "${i}"` : String(i)})`,
        ),
      );
  });

  it("after forgetBefore: a forgotten entry is refused, a kept one reads as before", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 40, packing: 0.2, seed: 5 }));
    tl.prolong({ events: 3000 });
    const twin = Timeline.fromScene(tl.toScene());
    twin.prolongTo(tl.horizon);
    tl.forgetBefore(tl.event(2500).time);
    expect(tl.firstEvent).toBeGreaterThan(0);
    expect(() => tl.eventDetail(tl.firstEvent - 1)).toThrow(
      /^eventDetail\(index\): must be at least \d+, the first entry kept \(got \d+\): event \d+ was forgotten/,
    );
    expect(() => tl.eventIndexAt(tl.historyStart - 1e-9)).toThrow(
      /^eventIndexAt\(t\): must be >= \S+ \(got /,
    );
    expect(tl.eventIndexAt(tl.historyStart)).toBe(tl.firstEvent);
    for (const i of [tl.firstEvent, tl.eventCount - 1])
      expect(tl.eventDetail(i)).toEqual(twin.eventDetail(i));
  });

  it("agrees with stateAt just before and just after every isolated collision of random frictionless scenes", () => {
    for (const seed of [1, 2, 3]) {
      const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.25, seed }));
      tl.prolong({ events: 600 });
      let checked = 0;
      for (let i = 1; i + 1 < tl.eventCount; i++) {
        const d = tl.eventDetail(i);
        const prev = tl.event(i - 1).time;
        const next = tl.event(i + 1).time;
        if (d.type === "action" || prev >= d.time || next <= d.time) continue;
        const before = tl.stateAt(d.time - Math.min(1e-9, (d.time - prev) / 2));
        const after = tl.stateAt(d.time);
        for (const b of d.bodies) {
          const sb = before.bodies.find((s) => s.id === b.id);
          const sa = after.bodies.find((s) => s.id === b.id);
          // no friction, no gravity: the velocity is constant between events, so exactly equal
          expect([b.before?.vx, b.before?.vy]).toEqual([sb?.vx, sb?.vy]);
          expect(b.after).toEqual(sa);
          const scale = Math.abs(b.before?.x ?? 0) + Math.abs(b.before?.y ?? 0) + 1;
          expect(Math.abs((b.before?.x ?? 0) - (sa?.x ?? 0))).toBeLessThan(1e-12 * scale);
          expect(Math.abs((b.before?.y ?? 0) - (sa?.y ?? 0))).toBeLessThan(1e-12 * scale);
        }
        checked++;
      }
      expect(checked).toBeGreaterThan(400);
    }
  });
});
