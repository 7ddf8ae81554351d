import { describe, expect, it } from "vitest";
import { compareIds, inNaturalOrder, naturalOrder } from "./naturalOrder";

describe("naturalOrder", () => {
  it("compares numbers inside ids by value", () => {
    const ids = ["d100", "d9", "ball10", "ball2", "a10b10", "a10b2", "B", "b"];
    expect(naturalOrder(ids).map((i) => ids[i])).toEqual([
      "B",
      "a10b2",
      "a10b10",
      "b",
      "ball2",
      "ball10",
      "d9",
      "d100",
    ]);
  });

  it("is a total order (distinct ids never compare equal) and cached per ids array", () => {
    expect(compareIds("a01", "a1")).not.toBe(0);
    expect(Math.sign(compareIds("a01", "a1"))).toBe(-Math.sign(compareIds("a1", "a01")));
    const ids = ["x2", "x1"];
    expect(naturalOrder(ids)).toBe(naturalOrder(ids));
  });

  it("lists lines and points (objects with an id) in natural order, the same array for the same input", () => {
    const points = [{ id: "p1" }, { id: "p10" }, { id: "p2" }, { id: "a" }];
    expect(inNaturalOrder(points).map((p) => p.id)).toEqual(["a", "p1", "p2", "p10"]);
    expect(inNaturalOrder(points)).toBe(inNaturalOrder(points));
    expect(points.map((p) => p.id)).toEqual(["p1", "p10", "p2", "a"]); // the frame's array is left as it was
  });

  it("orders 45,000 numbered ids by number", () => {
    const ids = Array.from({ length: 45_000 }, (_, i) => `d${i}`).sort();
    const order = naturalOrder(ids);
    expect(order.slice(0, 3).map((i) => ids[i])).toEqual(["d0", "d1", "d2"]);
    expect(ids[order[44_999]!]).toBe("d44999");
  });
});
