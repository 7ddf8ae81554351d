// The Event log's filter: one id, or a comma-separated list of ids that must all take part.
import { describe, expect, it } from "vitest";
import { eventFilter, filterParts } from "./eventFilter";

const passes = (text: string, ids: string[]) => eventFilter(text)?.(ids);

describe("eventFilter", () => {
  it("a blank text is no filter", () => {
    expect(eventFilter("")).toBeNull();
    expect(eventFilter("  ")).toBeNull();
  });

  it("one id keeps every entry it takes part in, obstacles included", () => {
    expect(passes("b1", ["b1", "b2"])).toBe(true);
    expect(passes(" b2 ", ["b1", "b2"])).toBe(true);
    expect(passes("floor", ["b1", "floor"])).toBe(true);
    expect(passes("b3", ["b1", "b2"])).toBe(false);
    expect(passes("b", ["b1", "b2"])).toBe(false);
  });

  it("a pair keeps the entries both take part in, in either order", () => {
    expect(passes("b1, b2", ["b1", "b2"])).toBe(true);
    expect(passes("b2,b1", ["b1", "b2"])).toBe(true);
    expect(passes("b1, b2", ["b1", "b3"])).toBe(false);
    expect(passes("b1, b2", ["b1"])).toBe(false);
  });

  it("a trailing or doubled comma is read as the ids it names", () => {
    expect(filterParts("b1,, b2 ,")).toEqual(["b1", "b2"]);
    expect(passes("b1,", ["b1"])).toBe(true);
  });

  it("an id holding a comma or spaces matches as a whole before being read as a list", () => {
    expect(passes("a, b", ["a, b", "wall"])).toBe(true);
    expect(passes("a, b", ["a", "b"])).toBe(true);
    expect(passes("left wall", ["d1", "left wall"])).toBe(true);
  });
});
