import { describe, expect, it } from "vitest";
import { unrepresentableNumbers } from "./jsonNumbers.js";

describe("unrepresentableNumbers", () => {
  it("finds the first literal that overflows, with its path, line and column", () => {
    const text = '{\n  "a": [1, 2e308],\n  "b": {"c": -1e999}\n}';
    expect(unrepresentableNumbers(text).overflow).toEqual({
      path: "a[1]",
      literal: "2e308",
      line: 2,
      column: 12,
    });
    expect(unrepresentableNumbers('{"b": {"c": -1e999}}').overflow).toMatchObject({
      path: "b.c",
      literal: "-1e999",
    });
  });

  it("finds none in range, at the edges, or inside strings", () => {
    const ok = '{"max": 1.7976931348623157e308, "min": 5e-324, "zero": 0e999, "s": "1e999", "k": [0.0, -0]}';
    expect(unrepresentableNumbers(ok)).toEqual({ overflow: null, underflow: new Map() });
  });

  it("lists literals with a non-zero digit that read as 0 or -0 (not a written zero)", () => {
    const text = '{"r": 1e-999, "v": [-2.5E-400, 0e-999], "x": 0.0}';
    expect([...unrepresentableNumbers(text).underflow]).toEqual([
      ["r", "1e-999"],
      ["v[0]", "-2.5E-400"],
    ]);
  });

  it("takes a literal of 400 digits without an exponent for what it is", () => {
    expect(unrepresentableNumbers(`[${"9".repeat(400)}]`).overflow).toMatchObject({ path: "[0]" });
    expect(unrepresentableNumbers(`[0.${"0".repeat(400)}1]`).underflow.get("[0]")).toBeDefined();
  });
});
