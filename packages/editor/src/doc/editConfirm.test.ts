import { describe, expect, it } from "vitest";
import type { Frame } from "../remote/protocol";
import { FRAME_STRIDE } from "../remote/protocol";
import { confirmEdit, stateBefore } from "./editConfirm";

const disc = { x: 40, y: 0, v: [0, 0] as [number, number], r: 20, m: 1, mu: 0 };

describe("confirmEdit", () => {
  it("a body's x and y together are a move, Undo moving it back", () => {
    expect(confirmEdit({ time: 2, type: "updateBody", id: "b3", x: 50, y: 0 }, disc)).toBe(
      'Moved disc "b3" to (50, 0) at t = 2 s (Undo moves it back to (40, 0)).',
    );
  });

  it("a velocity (dragged, or typed as vx, vy or |v|) and a cue strike give the velocity and the one Undo restores", () => {
    expect(confirmEdit({ time: 0.5, type: "giveVelocity", id: "b3", v: [2, -1] }, disc)).toBe(
      `Set disc "b3"'s velocity to (2, -1) at t = 0.5 s (Undo restores (0, 0)).`,
    );
    expect(confirmEdit({ time: 0.5, type: "updateBody", id: "b3", v: [2, 0] }, { ...disc, v: [1, 0] })).toBe(
      `Set disc "b3"'s velocity to (2, 0) at t = 0.5 s (Undo restores (1, 0)).`,
    );
    expect(confirmEdit({ time: 0, type: "giveVelocity", id: "b3", v: [-80, 1.5] }, disc, "strike")).toBe(
      'Struck disc "b3": velocity (-80, 1.5) at t = 0 s (Undo restores (0, 0)).',
    );
  });

  it("other fields as 'field = value', μ for mu and ∞ for an infinite mass, 6 digits", () => {
    expect(confirmEdit({ time: 1 / 3, type: "updateBody", id: "b3", r: 5 }, disc)).toBe(
      'Set disc "b3" r = 5 at t = 0.333333 s (Undo restores r = 20).',
    );
    expect(confirmEdit({ time: 1, type: "updateBody", id: "b3", m: Number.POSITIVE_INFINITY }, disc)).toBe(
      'Set disc "b3" m = ∞ at t = 1 s (Undo restores m = 1).',
    );
    expect(confirmEdit({ time: 1, type: "updateBody", id: "b3", mu: 0.25 }, disc)).toBe(
      'Set disc "b3" μ = 0.25 at t = 1 s (Undo restores μ = 0).',
    );
    expect(confirmEdit({ time: 1, type: "updateBody", id: "b3", x: 1.23456789 }, disc)).toBe(
      'Set disc "b3" x = 1.23457 at t = 1 s (Undo restores x = 40).',
    );
  });

  it("lines by their kind, points moved, the globals", () => {
    const line = { p1: [0, 0] as [number, number], p2: [10, 0] as [number, number], kind: "ray" };
    expect(confirmEdit({ time: 0, type: "updateLine", id: "l1", p2: [10, 5] }, line)).toBe(
      'Set ray "l1" p2 = (10, 5) at t = 0 s (Undo restores p2 = (10, 0)).',
    );
    expect(confirmEdit({ time: 0, type: "updateLine", id: "l1", kind: "segment" }, line)).toBe(
      'Set ray "l1" kind = segment at t = 0 s (Undo restores kind = ray).',
    );
    expect(confirmEdit({ time: 3, type: "updatePoint", id: "p1", p: [1, 2] }, { p: [0, 2] })).toBe(
      'Moved point "p1" to (1, 2) at t = 3 s (Undo moves it back to (0, 2)).',
    );
    expect(confirmEdit({ time: 0, type: "setGlobal", g: 1 }, { g: 9.81, gravity: [0, -9.81] })).toBe(
      "Set g = 1 at t = 0 s (Undo restores g = 9.81).",
    );
  });

  it("says when nothing changed, and without the state before says only that Undo takes it back", () => {
    expect(confirmEdit({ time: 0, type: "updateBody", id: "b3", r: 20 }, disc)).toBe(
      'Set disc "b3" r = 20 at t = 0 s (unchanged: Undo takes the action back).',
    );
    expect(confirmEdit({ time: 0, type: "updateBody", id: "b3", x: 1, y: 2 }, null)).toBe(
      'Moved disc "b3" to (1, 2) at t = 0 s (Undo takes it back).',
    );
    expect(confirmEdit({ time: 0, type: "updateBody", id: "b3", r: 2 }, null)).toBe(
      'Set disc "b3" r = 2 at t = 0 s (Undo takes it back).',
    );
  });
});

describe("stateBefore", () => {
  const data = new Float64Array(2 * FRAME_STRIDE);
  data.set([1, 2, 3, 4], FRAME_STRIDE); // b2 at (1, 2), velocity (3, 4)
  const frame = {
    t: 0,
    revision: 1,
    g: 9.81,
    gravity: [0, -1],
    ids: ["b1", "b2"],
    data,
    lines: [{ id: "l1", p1: [0, 0], p2: [1, 0], kind: "segment" }],
    points: [{ id: "p1", p: [5, 5] }],
  } as Frame;

  it("reads the edited object's fields from the frame, or null when it has no such object", () => {
    expect(stateBefore(frame, { time: 0, type: "updateBody", id: "b2", r: 1 })).toMatchObject({
      x: 1,
      y: 2,
      v: [3, 4],
    });
    expect(stateBefore(frame, { time: 0, type: "updateBody", id: "zz", r: 1 })).toBeNull();
    expect(stateBefore(frame, { time: 0, type: "updateLine", id: "l1", kind: "ray" })).toEqual({
      p1: [0, 0],
      p2: [1, 0],
      kind: "segment",
    });
    expect(stateBefore(frame, { time: 0, type: "updatePoint", id: "p1", p: [0, 0] })).toEqual({ p: [5, 5] });
    expect(stateBefore(frame, { time: 0, type: "setGlobal", g: 1 })).toEqual({ g: 9.81, gravity: [0, -1] });
  });
});
