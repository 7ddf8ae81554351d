import { describe, expect, it } from "vitest";
import { packFrame } from "../remote/packFrame";
import { frameBounds, hitTest } from "./hitTest";

const frame = packFrame(
  {
    time: 0,
    g: 9.81,
    gravity: [0, 0],
    bodies: [
      { id: "a", x: 0, y: 0, vx: 0, vy: 0, ax: 0, ay: 0, r: 2, m: 1, mu: 0 },
      { id: "b", x: 10, y: 0, vx: 1, vy: 0, ax: 0, ay: 0, r: 1, m: 1, mu: 0 },
    ],
    lines: [{ id: "wall", p1: [0, -10], p2: [1, -10], kind: "line" }],
    points: [{ id: "pin", p: [5, 5] }],
  },
  0,
);

describe("hitTest", () => {
  it("finds the disc, point or line under the pointer", () => {
    expect(hitTest(frame, [0.5, 1], 0.1)).toEqual({ kind: "body", id: "a" });
    expect(hitTest(frame, [10, 1.05], 0.1)).toEqual({ kind: "body", id: "b" });
    expect(hitTest(frame, [5.05, 5], 0.1)).toEqual({ kind: "point", id: "pin" });
    expect(hitTest(frame, [1000, -10.05], 0.1)).toEqual({ kind: "line", id: "wall" });
    expect(hitTest(frame, [5, 0], 0.1)).toBeNull();
  });

  it("bounds include disc radii, line ends and points", () => {
    expect(frameBounds(frame)).toEqual({ minX: -2, minY: -10, maxX: 11, maxY: 5 });
  });
});
