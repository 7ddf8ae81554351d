// Whether a small straight move passes across something (sweep.ts): a segment meeting a line, ray or
// segment, a point inside the region a moved segment sweeps, a point a moved line passes.
import { describe, expect, it } from "vitest";
import type { Vec2 } from "../engineTypes";
import { insideQuad, segmentMeetsLine, sidesDiffer } from "./sweep";

describe("segmentMeetsLine", () => {
  it("meets a line anywhere along it, a ray ahead of its start, a segment between its ends", () => {
    const a: Vec2 = [0, -1];
    const b: Vec2 = [0, 1];
    // the wall y = 0 through (5, 0) and (6, 0): the move at x = 0 crosses the line only
    expect(segmentMeetsLine(a, b, [5, 0], [6, 0], "line")).toBe(true);
    expect(segmentMeetsLine(a, b, [5, 0], [6, 0], "segment")).toBe(false);
    expect(segmentMeetsLine(a, b, [5, 0], [6, 0], "ray")).toBe(false);
    expect(segmentMeetsLine(a, b, [5, 0], [4, 0], "ray")).toBe(true);
    expect(segmentMeetsLine(a, b, [-1, 0], [1, 0], "segment")).toBe(true);
  });

  it("counts touching; a move that stops short or runs parallel does not meet it", () => {
    expect(segmentMeetsLine([0, -1], [0, 0], [-1, 0], [1, 0], "segment")).toBe(true);
    expect(segmentMeetsLine([0, -1], [0, -0.01], [-1, 0], [1, 0], "line")).toBe(false);
    expect(segmentMeetsLine([0, 1], [5, 1], [-1, 0], [1, 0], "line")).toBe(false);
    expect(segmentMeetsLine([0, 0], [0, 0], [-1, 0], [1, 0], "line")).toBe(false);
  });
});

describe("insideQuad", () => {
  it("holds the points strictly inside the hull of four corners, in any order, a bow-tie's too", () => {
    const square: [Vec2, Vec2, Vec2, Vec2] = [
      [0, 0],
      [2, 0],
      [2, 2],
      [0, 2],
    ];
    expect(insideQuad([1, 1], square)).toBe(true);
    expect(insideQuad([1.9, 0.1], square)).toBe(true);
    expect(insideQuad([2.1, 1], square)).toBe(false);
    expect(insideQuad([1, 0], square)).toBe(false); // on an edge: not strictly inside
    // crossed order (a segment whose ends swapped sides): the whole hull still counts
    expect(insideQuad([1, 0.2], [square[0], square[2], square[1], square[3]])).toBe(true);
    // a degenerate hull (a segment moved along itself) holds nothing
    expect(
      insideQuad(
        [1, 0],
        [
          [0, 0],
          [2, 0],
          [3, 0],
          [1, 0],
        ],
      ),
    ).toBe(false);
  });
});

describe("sidesDiffer", () => {
  it("says whether a line moved from p1p2 to ab passed q", () => {
    expect(sidesDiffer([0, 0.5], [-1, 1], [1, 1], [-1, 0], [1, 0])).toBe(true);
    expect(sidesDiffer([0, 0.5], [-1, 1], [1, 1], [-1, 0.6], [1, 0.6])).toBe(false);
    // on the new line: not passed (the placement check says whether it touches)
    expect(sidesDiffer([0, 0], [-1, 1], [1, 1], [-1, 0], [1, 0])).toBe(false);
    // a tilt passes points far along the line
    expect(sidesDiffer([100, 0.5], [0, 0], [1, 0], [0, 0], [1, 0.01])).toBe(true);
  });
});
