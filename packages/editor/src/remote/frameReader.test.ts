import { type SceneFile, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { Action } from "../engineTypes";
import { FrameReader } from "./frameReader";
import { packFrame } from "./packFrame";
import type { Frame } from "./protocol";

/** Three discs in a box with friction; later actions add a point, remove a wall and change g. */
function scene(): SceneFile {
  const actions: Action[] = [
    { time: 0, type: "addLine", id: "s", p1: [0, 0], p2: [20, 0], kind: "segment" },
    { time: 0, type: "addLine", id: "e", p1: [20, 0], p2: [20, 20], kind: "segment" },
    { time: 0, type: "addLine", id: "n", p1: [20, 20], p2: [0, 20], kind: "segment" },
    { time: 0, type: "addLine", id: "w", p1: [0, 20], p2: [0, 0], kind: "segment" },
    { time: 0, type: "addBody", id: "a", x: 3, y: 3, r: 1, m: 1, mu: 0.1, v: [6, 2] },
    { time: 0, type: "addBody", id: "b", x: 10, y: 4, r: 1.5, m: 2, mu: 0.1, v: [-3, 5] },
    { time: 0, type: "addBody", id: "c", x: 15, y: 15, r: 1, m: 1, mu: 0.1, v: [0, 0] },
    { time: 1, type: "addPoint", id: "pin", p: [5, 15] },
    { time: 2, type: "removeLine", id: "n" },
    { time: 2.5, type: "removeBody", id: "c" },
    { time: 3, type: "setGlobal", g: 2 },
  ];
  return { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions };
}

/** A timeline of `s` computed to `until`, with its stateAt calls counted. */
function counted(s: SceneFile, until?: number) {
  const tl = Timeline.fromScene(s, { compute: false });
  if (until !== undefined) tl.prolongTo(until);
  const calls = { stateAt: 0 };
  const stateAt = tl.stateAt.bind(tl);
  const timeline = Object.assign(tl, {
    stateAt: (t: number) => {
      calls.stateAt++;
      return stateAt(t);
    },
  });
  return { tl: timeline, calls, stateAt };
}

/**
 * Expect `f` to be exactly the frame packFrame(stateAt(t), revision, previous) gives: numbers bit
 * for bit (toStrictEqual compares with Object.is), the same ids, and the previous frame's ids array
 * carried over exactly when packFrame carries it.
 */
function expectFrame(f: Frame, expected: Frame, previous: string[] | null = null): void {
  expect(Array.from(f.data)).toStrictEqual(Array.from(expected.data));
  expect(f.ids).toStrictEqual(expected.ids);
  expect(f.ids === previous).toBe(expected.ids === previous);
  expect({ ...f, data: null, ids: null }).toStrictEqual({ ...expected, data: null, ids: null });
}

describe("FrameReader", () => {
  it("gives packFrame(stateAt(t)) at every time, forwards, backwards and across actions that change lines, points, bodies and g", () => {
    const { tl, stateAt } = counted(scene(), 5);
    const reader = new FrameReader();
    const times = [
      ...Array.from({ length: 51 }, (_, k) => k / 10), // playback over every action
      4.95,
      0.5,
      2.5,
      2.49,
      1,
      0,
      3.2,
      5,
    ];
    let previous: string[] | null = null;
    for (const t of times) {
      const f = reader.frame(tl, t, 7, previous);
      expectFrame(f, packFrame(stateAt(t), 7, previous), previous);
      previous = f.ids;
    }
  });

  it("reads stateAt only when the lines, points or fields may differ, bodies from bodyArraysAt otherwise", () => {
    const { tl, calls } = counted(scene(), 5);
    const reader = new FrameReader();
    for (let k = 0; k < 20; k++) reader.frame(tl, 0.04 * k, 0, null); // before the first later action
    expect(calls.stateAt).toBe(1);
    reader.frame(tl, 1, 0, null); // the point is added at t = 1
    reader.frame(tl, 1.5, 0, null);
    expect(calls.stateAt).toBe(2);
    reader.frame(tl, 0.5, 0, null); // back before it
    expect(calls.stateAt).toBe(3);
    tl.prolongTo(6); // computed further: nothing before the old horizon can change
    reader.frame(tl, 0.6, 0, null);
    expect(calls.stateAt).toBe(3);
    tl.setActions(tl.actions.slice(0, -1)); // an edit: the frame is read whole again
    reader.frame(tl, 0.6, 0, null);
    expect(calls.stateAt).toBe(4);
    const other = counted(scene(), 5);
    const f = reader.frame(other.tl, 0.6, 0, null); // another timeline (a load)
    expect(other.calls.stateAt).toBe(1);
    expectFrame(f, packFrame(other.stateAt(0.6), 0, null));
  });

  it("at the horizon, shows the actions a later slice logs at that same instant", () => {
    // a meets the wall at t = 1 with the point's action at t = 1: a prolong stopped after the
    // collision leaves the horizon at 1 with the action still to apply; the next one applies it
    const s: SceneFile = {
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, 0],
      actions: [
        { time: 0, type: "addLine", id: "wall", p1: [2, 0], p2: [2, 1], kind: "line" },
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [1, 0] },
        { time: 1, type: "addPoint", id: "p", p: [-9, 9] },
      ],
    };
    const { tl, stateAt } = counted(s);
    const reader = new FrameReader();
    tl.prolong({ events: 1 });
    expect(tl.horizon).toBe(1);
    expect(reader.frame(tl, 1, 0, null).points).toStrictEqual([]);
    tl.prolong({ events: 1 });
    expect(tl.horizon).toBe(1);
    const f = reader.frame(tl, 1, 0, null);
    expect(f.points.map((p) => p.id)).toStrictEqual(["p"]);
    expectFrame(f, packFrame(stateAt(1), 0, null));
  });

  it("carries the previous frame's ids array while the ids are unchanged, a new one when they change", () => {
    const { tl } = counted(scene(), 5);
    const reader = new FrameReader();
    const first = reader.frame(tl, 0.1, 0, null);
    const second = reader.frame(tl, 0.2, 0, first.ids);
    expect(second.ids).toBe(first.ids);
    expect(reader.frame(tl, 0.3, 0, second.ids).ids).toBe(first.ids);
    const copy = [...first.ids]; // the same ids in another array (sent by a stateAt frame, say)
    expect(reader.frame(tl, 0.4, 0, copy).ids).toBe(copy);
    const removed = reader.frame(tl, 2.6, 0, copy); // c was removed at t = 2.5
    expect(removed.ids).not.toBe(copy);
    expect(removed.ids).toStrictEqual(["a", "b"]);
    const later = reader.frame(tl, 2.7, 0, removed.ids);
    expect(later.ids).toBe(removed.ids);
    expect(reader.frame(tl, 2.8, 0, null).ids).toStrictEqual(["a", "b"]); // nothing sent yet
  });
});
