/**
 * A refused edit changes nothing, now that an edit keeps only what it can change (undo.ts EditScope:
 * the audit of session 20 found every apply copying every action and keyframe ever, so a game
 * applying one action a frame slowed down without bound). Refusals forward, in the past (a later
 * action made invalid, a Zeno state in the recomputed future), after a forget and by setActions,
 * each followed by more edits that must match a timeline built from scratch; and the storage an
 * apply keeps is the same arrays, not copies.
 */
import { describe, expect, it } from "vitest";
import { SceneError } from "../scene/errors.js";
import type { Action } from "../scene/types.js";
import { SimulationError } from "../sim/errors.js";
import { STRIDE } from "./motionTable.js";
import { coreOf, disc, fingerprint } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const BOX: Action[] = [
  { time: 0, type: "addLine", id: "L", p1: [-10, -10], p2: [-10, 10], kind: "line" },
  { time: 0, type: "addLine", id: "R", p1: [10, -10], p2: [10, 10], kind: "line" },
  { time: 0, type: "addLine", id: "B", p1: [-10, -10], p2: [10, -10], kind: "line" },
  { time: 0, type: "addLine", id: "T", p1: [-10, 10], p2: [10, 10], kind: "line" },
];

/** Discs bouncing in a box, computed to t = 40 (many periodic keyframes: one every 1024 events). */
function busy(): Timeline {
  const tl = new Timeline({ g: 0 });
  tl.setActions([
    ...BOX,
    disc("a", -5, 0, [3, 1]),
    disc("b", 5, 0, [-2, 2.5]),
    disc("c", 0, 5, [1.5, -3]),
    disc("d", 0, -5, [-2.5, -1]),
  ]);
  tl.prolongTo(40);
  return tl;
}

/** The timeline's scene built again from scratch, computed to its horizon: what it must show. */
function fromScratch(tl: Timeline): unknown {
  const ref = Timeline.fromScene(tl.toScene());
  ref.prolongTo(tl.horizon);
  return fingerprint(ref);
}

function refused(f: () => void, kind: typeof SceneError | typeof SimulationError): void {
  expect(f).toThrow(kind);
}

describe("refused edits change nothing (an edit keeps only what it can change)", () => {
  it("forward: an addBody overlapping at the horizon, then valid edits", () => {
    const tl = busy();
    const before = fingerprint(tl);
    const where = tl.stateAt(40).bodies.find((b) => b.id === "a");
    refused(
      () => tl.apply({ time: 40, type: "addBody", id: "e", x: where?.x ?? 0, y: where?.y ?? 0, r: 1, m: 1 }),
      SceneError,
    );
    expect(fingerprint(tl)).toStrictEqual(before);
    tl.apply({ time: 40, type: "giveVelocity", id: "a", v: [0, 4] });
    tl.prolongTo(60);
    expect(fingerprint(tl)).toStrictEqual(fromScratch(tl));
  });

  it("in the past: an edit that makes a later action invalid, then an edit in the past that is valid", () => {
    const tl = busy();
    tl.apply({ time: 30, type: "removeBody", id: "d" });
    const before = fingerprint(tl);
    // removing d at t = 12 leaves the removal at t = 30 without its body
    refused(() => tl.apply({ time: 12, type: "removeBody", id: "d" }), SceneError);
    expect(fingerprint(tl)).toStrictEqual(before);
    tl.apply({ time: 12, type: "giveVelocity", id: "c", v: [-1, 2] });
    expect(fingerprint(tl)).toStrictEqual(fromScratch(tl));
  });

  it("in the past: an edit whose recomputed future meets a Zeno state", () => {
    const tl = new Timeline({ g: 0 });
    // f rests on a shelf of its own, out of the box
    const shelf: Action = { time: 0, type: "addLine", id: "F", p1: [50, -1], p2: [60, -1], kind: "segment" };
    tl.setActions([...BOX, shelf, disc("a", -5, 0, [3, 1]), disc("b", 5, 0, [-2, 2.5]), disc("f", 55, 0)]);
    tl.prolongTo(30);
    const before = fingerprint(tl);
    // from t = 10, gravity presses f onto its shelf: resting contact, refused
    refused(() => tl.apply({ time: 10, type: "setGlobal", gravity: [0, -1] }), SimulationError);
    expect(fingerprint(tl)).toStrictEqual(before);
    tl.apply({ time: 10, type: "giveVelocity", id: "b", v: [1, 1] });
    expect(fingerprint(tl)).toStrictEqual(fromScratch(tl));
  });

  it("after forgetBefore, and by setActions", () => {
    const tl = busy();
    tl.forgetBefore(20);
    const before = fingerprint(tl);
    refused(() => tl.apply({ time: 25, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }), SceneError);
    expect(fingerprint(tl)).toStrictEqual(before);
    refused(() => tl.setActions([...tl.actions, { time: 30, type: "removeBody", id: "zz" }]), SceneError);
    expect(fingerprint(tl)).toStrictEqual(before);
    tl.apply({ time: 25, type: "giveVelocity", id: "a", v: [2, 0] });
    tl.setActions([...tl.actions, { time: 30, type: "removeBody", id: "b" }]);
    const twin = busy();
    twin.apply({ time: 25, type: "giveVelocity", id: "a", v: [2, 0] });
    twin.apply({ time: 30, type: "removeBody", id: "b" });
    expect(tl.stateAt(40)).toStrictEqual(twin.stateAt(40));
    expect(tl.eventsBetween(20, 40)).toStrictEqual(
      twin.eventsBetween(20, 40).slice(-tl.eventsBetween(20, 40).length),
    );
  });

  it("forward: refused after computing events on the way, with a body removed before: the motions restored", () => {
    const tl = busy();
    tl.apply({ time: 20, type: "removeBody", id: "d" });
    tl.apply({ time: 25, type: "addBody", id: "d", x: 0, y: 0, r: 0.5, m: 1, v: [1, 2] });
    tl.prolongTo(40);
    const before = fingerprint(tl);
    const table = () => Array.from(coreOf(tl).table.data.subarray(0, coreOf(tl).bodyIds.length * STRIDE));
    const motions = table();
    // where a will be at t = 50 (found on a twin): a disc added there at 50 is refused, after the
    // computation from 40 to 50 rebased every moving body's motion
    const twin = Timeline.fromScene(tl.toScene());
    twin.prolongTo(50);
    const a = twin.stateAt(50).bodies.find((b) => b.id === "a");
    refused(
      () => tl.apply({ time: 50, type: "addBody", id: "e", x: a?.x ?? 0, y: a?.y ?? 0, r: 1, m: 1 }),
      SceneError,
    );
    expect(fingerprint(tl)).toStrictEqual(before);
    expect(table()).toStrictEqual(motions);
    // keyframes taken from here on come from the motions restored
    tl.prolongTo(90);
    expect(fingerprint(tl)).toStrictEqual(fromScratch(tl));
  });

  it("an apply keeps the action list and the keyframes in place instead of copying them", () => {
    const tl = busy();
    const c = coreOf(tl);
    const acts = c.acts;
    const keyframes = c.keyframes;
    const ids = c.bodyIds;
    tl.apply({ time: 40, type: "giveVelocity", id: "a", v: [1, 1] });
    tl.apply({ time: 20, type: "giveVelocity", id: "b", v: [1, -1] });
    expect(coreOf(tl).acts).toBe(acts);
    expect(coreOf(tl).keyframes).toBe(keyframes);
    expect(coreOf(tl).bodyIds).toBe(ids);
    expect(fingerprint(tl)).toStrictEqual(fromScratch(tl));
  });

  it("without history too, also when a later action at the instant joins its group (review of session 20)", () => {
    const tl = new Timeline({ g: 0, history: false });
    tl.setActions([...BOX, disc("a", -5, 0, [3, 1]), disc("b", -3, 0)]);
    tl.prolongTo(10);
    const acts = coreOf(tl).acts;
    tl.apply({ time: 10, type: "giveVelocity", id: "a", v: [1, 0] });
    tl.apply({ time: 10, type: "giveVelocity", id: "b", v: [0, 1] });
    tl.apply({ time: 12, type: "giveVelocity", id: "b", v: [0, -1] });
    expect(coreOf(tl).acts).toBe(acts);
    tl.prolongTo(30);
    const ref = Timeline.fromScene(tl.toScene());
    ref.prolongTo(30);
    expect(tl.stateAt(30)).toStrictEqual(ref.stateAt(30));
    expect(tl.counts()).toStrictEqual(ref.counts());
  });
});
