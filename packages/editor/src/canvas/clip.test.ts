import { describe, expect, it } from "vitest";
import { clipToRect, distanceToLine } from "./clip";

const rect = { minX: 0, minY: 0, maxX: 10, maxY: 10 };

describe("clipToRect", () => {
  it("an infinite line reaches both edges of the view", () => {
    expect(clipToRect([4, 5], [6, 5], "line", rect)).toEqual([
      [0, 5],
      [10, 5],
    ]);
  });

  it("a ray starts at p1 and reaches one edge", () => {
    expect(clipToRect([4, 5], [6, 5], "ray", rect)).toEqual([
      [4, 5],
      [10, 5],
    ]);
  });

  it("a segment is kept as is when inside, and cut when it leaves", () => {
    expect(clipToRect([1, 1], [2, 3], "segment", rect)).toEqual([
      [1, 1],
      [2, 3],
    ]);
    expect(clipToRect([5, 5], [15, 5], "segment", rect)).toEqual([
      [5, 5],
      [10, 5],
    ]);
  });

  it("something entirely outside gives null, also when parallel to an edge", () => {
    expect(clipToRect([-5, 20], [5, 20], "line", rect)).toBeNull();
    expect(clipToRect([12, 5], [20, 5], "ray", rect)).toBeNull();
    expect(clipToRect([-3, -3], [-1, -1], "segment", rect)).toBeNull();
  });
});

describe("distanceToLine", () => {
  it("measures to the nearest point of each kind", () => {
    expect(distanceToLine([-3, 4], [0, 0], [1, 0], "line")).toBe(4);
    expect(distanceToLine([-3, 4], [0, 0], [1, 0], "ray")).toBe(5);
    expect(distanceToLine([4, 4], [0, 0], [1, 0], "segment")).toBe(5);
  });
});
