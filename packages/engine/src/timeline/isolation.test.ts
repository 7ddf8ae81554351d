/**
 * What a Timeline hands out cannot change it behind its back: the scene from toScene() and the
 * actions list are the caller's to edit (copies) or read-only (frozen), and reading methods refuse a
 * time that is not a number instead of answering something.
 */
import { describe, expect, it } from "vitest";
import type { Action } from "../scene/types.js";
import { Timeline } from "./timeline.js";

function twoDiscs(): Timeline {
  const tl = new Timeline({ g: 0 });
  tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1, v: [1, 0] });
  tl.apply({ time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 });
  tl.prolong({ time: 10 });
  return tl;
}

describe("Timeline isolation", () => {
  it("editing the scene from toScene() changes nothing in the timeline (it shared the action objects)", () => {
    const tl = twoDiscs();
    const before = JSON.stringify(tl.toScene());
    const scene = tl.toScene();
    const b = scene.actions[1] as Action & { x: number };
    b.x = 5.5; // into a: never validated
    const a = scene.actions[0] as unknown as { v: number[] };
    a.v[0] = 7;
    (scene.gravity as unknown as number[])[1] = -10;
    expect(JSON.stringify(tl.toScene())).toBe(before);
    expect(tl.actions[1]).toMatchObject({ x: 10 });
    // and a recompute from scratch still sees the original scene
    tl.setActions([]);
    tl.setActions(JSON.parse(before).actions);
    tl.prolong({ time: 10 });
    expect(tl.stateAt(10).gravity).toEqual([0, 0]);
    expect(tl.stateAt(10).bodies.map((s) => [s.id, s.x])).toEqual([
      ["a", 8],
      ["b", 17],
    ]);
  });

  it("editing a state from stateAt() changes nothing (its lines, points and gravity were the keyframe's)", () => {
    const build = () => {
      const tl = new Timeline({ g: 0 });
      tl.apply({ time: 0, type: "addLine", id: "wall", p1: [0, -10], p2: [0, 10], kind: "line" });
      tl.apply({ time: 0, type: "addPoint", id: "pin", p: [50, 0] });
      tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1, v: [-1, 0] });
      tl.prolong({ time: 10 });
      return tl;
    };
    const tl = build();
    const s = tl.stateAt(2);
    (s.lines[0]?.p1 as unknown as number[])[0] = 3; // the wall moved into the disc's path
    (s.points[0]?.p as unknown as number[])[0] = 7;
    (s.gravity as unknown as number[])[0] = 7;
    const fresh = build();
    expect(tl.stateAt(6)).toEqual(fresh.stateAt(6));
    // a recompute from the keyframe (an edit in the past) still sees the real wall and pin
    tl.apply({ time: 1, type: "giveVelocity", id: "a", v: [1, 0] });
    fresh.apply({ time: 1, type: "giveVelocity", id: "a", v: [1, 0] });
    expect(tl.stateAt(10)).toEqual(fresh.stateAt(10));
    expect(tl.counts()).toEqual(fresh.counts());
  });

  it("toScene keeps the scene's meta (fromScene dropped it: a saved view or title was lost), as a copy", () => {
    const meta = { title: "break", view: { x: 1, y: 2, zoom: 3 } };
    const tl = Timeline.fromScene({
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, 0],
      actions: [],
      meta,
    });
    const scene = tl.toScene();
    expect(scene.meta).toEqual(meta);
    (scene.meta as { view: { x: number } }).view.x = 99;
    meta.view.y = 99;
    expect(tl.toScene().meta).toEqual({ title: "break", view: { x: 1, y: 2, zoom: 3 } });
    expect("meta" in new Timeline().toScene()).toBe(false);
  });

  it("the actions it lists are read-only: writing one throws instead of changing the history's input", () => {
    const tl = twoDiscs();
    const a = tl.actions[1] as { x: number };
    expect(() => {
      a.x = 6;
    }).toThrow(TypeError);
    const v = (tl.actions[0] as unknown as { v: number[] }).v;
    expect(() => {
      v[0] = 7;
    }).toThrow(TypeError);
    expect(tl.actions[1]).toMatchObject({ x: 10 });
  });

  it("an action object given to apply() stays the caller's (edits to it later change nothing)", () => {
    const tl = new Timeline({ g: 0 });
    const add = {
      time: 0,
      type: "addBody" as const,
      id: "a",
      x: 0,
      y: 0,
      r: 1,
      m: 1,
      v: [1, 0] as [number, number],
    };
    tl.apply(add);
    add.x = 50;
    add.v[0] = 3;
    expect(tl.actions[0]).toMatchObject({ x: 0, v: [1, 0] });
    add.x = 0;
    expect(Object.isFrozen(add)).toBe(false);
  });

  it("nextEventTime, prevEventTime and eventsBetween refuse a time that is not a number (NaN gave 0)", () => {
    const tl = twoDiscs();
    expect(() => tl.nextEventTime(Number.NaN)).toThrow("nextEventTime(t): must be a number (got NaN)");
    expect(() => tl.prevEventTime(Number.NaN)).toThrow("prevEventTime(t): must be a number (got NaN)");
    expect(() => tl.eventsBetween(Number.NaN, 1)).toThrow("eventsBetween(t0): must be a number (got NaN)");
    expect(() => tl.eventsBetween(0, Number.NaN)).toThrow("eventsBetween(t1): must be a number (got NaN)");
    expect(tl.nextEventTime(-1)).toBe(0);
    expect(tl.prevEventTime(Number.POSITIVE_INFINITY)).toBe(3);
    expect(tl.eventsBetween(0, Number.POSITIVE_INFINITY)).toHaveLength(3);
  });
});

describe("Timeline subscribers", () => {
  it("a listener that throws does not keep the others from being told; its error comes after them", () => {
    const tl = new Timeline({ g: 0 });
    const told: string[] = [];
    tl.subscribe(() => told.push("first"));
    tl.subscribe(() => {
      throw new Error("listener bug");
    });
    tl.subscribe(() => told.push("third"));
    expect(() => tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 })).toThrow(
      "listener bug",
    );
    expect(told).toEqual(["first", "third"]);
    expect(tl.actions).toHaveLength(1); // the change itself was made
    expect(tl.getSnapshot()).toBe(1);
  });

  it("subscribe refuses a listener that is not a function (the next apply() failed instead)", () => {
    const tl = new Timeline({ g: 0 });
    expect(() => tl.subscribe(undefined as unknown as () => void)).toThrow(
      /^subscribe\(listener\): must be a function \(got /,
    );
    expect(() => tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 })).not.toThrow();
  });
});
