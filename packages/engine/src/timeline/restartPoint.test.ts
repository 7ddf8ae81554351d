/**
 * The restart points between and before an instant's actions (restartPoint.ts) and the keyframe
 * owed after an instant's actions (checkpoint.ts): where an edit at the horizon restarts, how many
 * keyframes a build one action per apply takes, and that every such path gives what building from
 * scratch gives.
 */
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { Action, SceneFile } from "../scene/types.js";
import { coreOf } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const EDITOR = { keepHorizon: false, checkLater: false };

function expectSameAsScratch(tl: Timeline): void {
  const h = tl.horizon;
  const scratch = Timeline.fromScene(tl.toScene());
  scratch.prolongTo(h);
  expect(tl.counts()).toStrictEqual(scratch.counts());
  expect(tl.eventsBetween(0, h)).toStrictEqual(scratch.eventsBetween(0, h));
  for (const t of [0, h / 2, h]) expect(tl.stateAt(t)).toStrictEqual(scratch.stateAt(t));
}

/** A gas computed for 3,000 events by a compute: false timeline (the editor's). */
function editorGas(): { tl: Timeline; scene: SceneFile } {
  const scene = dilutedGas({ n: 100, packing: 0.15, seed: 3 });
  const tl = Timeline.fromScene(scene, { compute: false });
  tl.prolong({ events: 3000 });
  return { tl, scene };
}

const push = (t: number, id: string, v: [number, number]): Action => ({
  time: t,
  type: "giveVelocity",
  id,
  v,
});

describe("restart points inside an instant", () => {
  it("taking back the only action at the horizon restarts at its instant, not at the keyframe before", () => {
    const { tl } = editorGas();
    const t = tl.horizon;
    const before = coreOf(tl).keyframes.at(-1)?.time as number;
    expect(before).toBeLessThan(t); // the last keyframe lies before the instant
    tl.apply(push(t, "d7", [0.5, 0.5]), EDITOR);
    const list = tl.actions.slice(0, -1);
    tl.setActions(list); // compute: false stays at the restart point
    expect(tl.horizon).toBe(t);
    tl.apply(push(t, "d7", [0.25, -0.5]), EDITOR);
    tl.prolong({ events: 500 });
    expectSameAsScratch(tl);
  });

  it("taking back the last actions of an instant one by one restarts between them", () => {
    const { tl } = editorGas();
    const t = tl.horizon;
    tl.apply(push(t, "d1", [0.5, 0]), EDITOR);
    tl.stateAt(t); // the editor reads after each edit: the keyframe after it is taken
    tl.apply(push(t, "d2", [0, 0.5]), EDITOR);
    tl.stateAt(t);
    tl.apply(push(t, "d3", [-0.5, 0]), EDITOR);
    tl.stateAt(t);
    const n = tl.actions.length;
    tl.setActions(tl.actions.slice(0, n - 1)); // back to after d2's action (the spare)
    expect(tl.horizon).toBe(t);
    expect(coreOf(tl).applied).toBe(n - 1);
    tl.prolongTo(t);
    expectSameAsScratch(tl);
    tl.setActions(tl.actions.slice(0, n - 2)); // the spare is past this change: an earlier point
    tl.prolongTo(t);
    expect(tl.actions.length).toBe(n - 2);
    expectSameAsScratch(tl);
    tl.apply(push(t, "d4", [0.5, 0.5]), EDITOR);
    tl.prolong({ events: 500 });
    expectSameAsScratch(tl);
  });

  it("an action inserted before the last one of an instant restarts between the instant's actions", () => {
    const { tl } = editorGas();
    const t = tl.horizon;
    tl.apply(push(t, "d1", [0.5, 0]), EDITOR);
    tl.stateAt(t);
    tl.apply(push(t, "d2", [0, 0.5]), EDITOR);
    tl.stateAt(t);
    tl.prolong({ events: 300 });
    // the same actions, the new one between the two: the first change is the second action there
    const list = tl.actions.slice();
    list.splice(list.length - 1, 0, push(t, "d5", [-0.5, -0.5]));
    tl.setActions(list);
    tl.prolongTo(t);
    expectSameAsScratch(tl);
  });
});

describe("a scene built one action per apply", () => {
  const line = (i: number): Action => ({
    time: 0,
    type: "addLine",
    id: `s${i}`,
    kind: "segment",
    p1: [(i % 10) * 4, Math.floor(i / 10) * 4],
    p2: [(i % 10) * 4 + 2, Math.floor(i / 10) * 4],
  });

  it("owes the keyframe after the instant's actions until something reads it", () => {
    const tl = new Timeline({ g: 0 });
    for (let i = 0; i < 50; i++) tl.apply(line(i));
    const core = coreOf(tl);
    expect(core.rawKeyframes.length).toBe(1); // the start's only: none taken per apply
    expect(core.owed).not.toBeNull();
    expect(tl.stateAt(0).lines.length).toBe(50);
    expect(core.rawKeyframes.length).toBe(2);
    expect(core.owed).toBeNull();
    tl.apply({ time: 0, type: "addBody", id: "a", x: 1, y: -3, r: 1, m: 1, v: [0, 1] });
    tl.prolongTo(10);
    expectSameAsScratch(tl);
    const scratch = Timeline.fromScene(tl.toScene());
    scratch.prolongTo(10);
    expect(tl.event(tl.eventCount - 1)).toStrictEqual(scratch.event(scratch.eventCount - 1));
    expect(tl.eventDetail(50)).toStrictEqual(scratch.eventDetail(50)); // the addBody entry
  });

  it("a refused action after many at the same instant changes nothing, and the next ones go on", () => {
    const tl = new Timeline({ g: 0 });
    for (let i = 0; i < 20; i++) tl.apply(line(i));
    tl.apply({ time: 0, type: "addBody", id: "a", x: 1, y: -3, r: 1, m: 1 });
    // overlaps s0 (y = 0 from x = 0 to 2)
    expect(() => tl.apply({ time: 0, type: "addBody", id: "b", x: 1, y: 0.5, r: 1, m: 1 })).toThrow(
      /overlap/,
    );
    expect(() => tl.apply(line(3))).toThrow(/s3/);
    tl.apply({ time: 0, type: "addBody", id: "b", x: 5, y: -3, r: 1, m: 1, v: [0, 1] });
    tl.prolongTo(5);
    expect(tl.actions.length).toBe(22);
    expectSameAsScratch(tl);
  });
});
