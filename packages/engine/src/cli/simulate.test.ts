// simulate (simulate.ts): where it stops and why (--until-time, idle, the scene's own untils).
import { describe, expect, it } from "vitest";
import { runCli } from "./run.js";
import { io, sceneText } from "./testSupport.js";

describe("simulate: where it stops and why", () => {
  it("simulate --until-time T stops at T when an action is still scheduled after T (it printed t = 0)", () => {
    const late = sceneText([
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
      { time: 5, type: "addBody", id: "b", x: 20, y: 0, r: 1, m: 1, v: [-1, 0] },
    ]);
    const { cli, out } = io({ "late.json": late });
    expect(runCli(["simulate", "late.json", "--until-time", "2"], cli)).toBe(0);
    const r = JSON.parse(out.stdout);
    expect(r.time).toBe(2);
    expect(r.bodies.map((b: { id: string; x: number }) => [b.id, b.x])).toEqual([["a", 2]]);
  });

  it("simulate --until-time T prints the bodies at T when no event is left before T (it printed the last event's time)", () => {
    const files = {
      "pair.json": sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
        { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
      ]),
    };
    const atT = io(files);
    expect(runCli(["simulate", "pair.json", "--until-time", "30"], atT.cli)).toBe(0);
    const r = JSON.parse(atT.out.stdout);
    // a stops at 3 where b was hit; b glides on at 1 from x = 5: x = 32 at t = 30
    expect(r).toMatchObject({ time: 30, reason: "idle", events: 1 });
    expect(r.bodies.map((b: { id: string; x: number; vx: number }) => [b.id, b.x, b.vx])).toEqual([
      ["a", 3, 0],
      ["b", 32, 1],
    ]);
    // Without a time bound the run stops at its last event; an event bound says so.
    const open = io(files);
    expect(runCli(["simulate", "pair.json"], open.cli)).toBe(0);
    expect(JSON.parse(open.out.stdout)).toMatchObject({ time: 3, reason: "idle" });
    // An event limit that lands on the last event: nothing is left, so the run is idle at T (review).
    const capped = io(files);
    expect(runCli(["simulate", "pair.json", "--max-events", "1", "--until-time", "30"], capped.cli)).toBe(0);
    expect(JSON.parse(capped.out.stdout)).toMatchObject({ time: 30, reason: "idle" });
  });

  it("reason is idle when only discs gliding across grid cells are left (the queue still held crossings: it said time)", () => {
    // 40 discs at rest 10 apart (enough for the grid) and one gliding past them all: no event ever.
    const actions: unknown[] = [
      { time: 0, type: "addBody", id: "glider", x: -5, y: 50, r: 1, m: 1, v: [1, 0] },
    ];
    for (let i = 0; i < 40; i++)
      actions.push({
        time: 0,
        type: "addBody",
        id: `s${i}`,
        x: 10 * (i % 8),
        y: 10 * Math.floor(i / 8),
        r: 1,
        m: 1,
      });
    const files = { "glide.json": sceneText(actions) };
    const idle = io(files);
    expect(runCli(["simulate", "glide.json", "--until-time", "10"], idle.cli)).toBe(0);
    expect(JSON.parse(idle.out.stdout)).toMatchObject({ time: 10, reason: "idle", events: 0 });
    // With an event still to come, the time limit is the reason.
    const wall = { time: 0, type: "addLine", id: "wall", p1: [200, 0], p2: [200, 100], kind: "segment" };
    const timed = io({ "hit.json": sceneText([...actions, wall]) });
    expect(runCli(["simulate", "hit.json", "--until-time", "10"], timed.cli)).toBe(0);
    expect(JSON.parse(timed.out.stdout)).toMatchObject({ time: 10, reason: "time", events: 0 });
  });
});

describe("simulate honours the scene's own until when the command line gives no bound", () => {
  // a disc between two walls (it never rests); the addBody's until says how far to compute
  const box = (until: unknown) =>
    sceneText([
      { time: 0, type: "addLine", id: "l", p1: [-10, -5], p2: [-10, 5], kind: "line" },
      { time: 0, type: "addLine", id: "r", p1: [10, -5], p2: [10, 5], kind: "line" },
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [3, 0], until },
      { time: 2, type: "giveVelocity", id: "a", v: [-5, 0] },
    ]);

  it('until { time: 30 }: up to t = 30, "reason": "until", the state --until-time 30 gives (it ran for ever)', () => {
    const files = { "box.json": box({ time: 30 }) };
    const own = io(files);
    expect(runCli(["simulate", "box.json"], own.cli)).toBe(0);
    const r = JSON.parse(own.out.stdout);
    expect(r).toMatchObject({ time: 30, reason: "until", events: 7 });
    const timed = io(files);
    expect(runCli(["simulate", "box.json", "--until-time", "30"], timed.cli)).toBe(0);
    expect({ ...JSON.parse(timed.out.stdout), reason: "until" }).toEqual(r);
  });

  it("until { events: 5 }: five events after the action; the command line's bounds win", () => {
    const files = { "box.json": box({ events: 5 }) };
    const own = io(files);
    expect(runCli(["simulate", "box.json"], own.cli)).toBe(0);
    expect(JSON.parse(own.out.stdout)).toMatchObject({ reason: "until", events: 5 });
    const events = io(files);
    expect(runCli(["simulate", "box.json", "--max-events", "2"], events.cli)).toBe(0);
    expect(JSON.parse(events.out.stdout)).toMatchObject({ reason: "events", events: 2 });
    const time = io(files);
    expect(runCli(["simulate", "box.json", "--until-time", "50"], time.cli)).toBe(0);
    expect(JSON.parse(time.out.stdout)).toMatchObject({ time: 50, reason: "time" });
  });

  it("a scene idle before its bound: reason idle, the bodies at the bound (they glide on)", () => {
    const files = {
      "pair.json": sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0], until: { time: 30 } },
        { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
      ]),
    };
    const { cli, out } = io(files);
    expect(runCli(["simulate", "pair.json"], cli)).toBe(0);
    const r = JSON.parse(out.stdout);
    expect(r).toMatchObject({ time: 30, reason: "idle", events: 1 });
    expect(r.bodies.map((b: { id: string; x: number }) => [b.id, b.x])).toEqual([
      ["a", 3],
      ["b", 32],
    ]);
  });
});
