import { describe, expect, it } from "vitest";
import { followRow } from "./useFollowTime";

describe("followRow", () => {
  const times = [0, 0, 0.5, 1, 1, 2, 3];
  it("puts the first row at or after t a few rows below the top", () => {
    expect(followRow(times, 2, 3)).toBe(2);
    expect(followRow(times, 1, 3)).toBe(0);
    expect(followRow(times, 1, 1)).toBe(2);
    expect(followRow(times, 1.5, 1)).toBe(4);
  });
  it("with every row in the past, shows the last ones; with none, the top", () => {
    expect(followRow(times, 9, 3)).toBe(4);
    expect(followRow([], 1, 3)).toBe(0);
  });
});
