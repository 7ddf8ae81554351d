import { describe, expect, it } from "vitest";
import { focusAfterRemoval } from "./removeFocus";

describe("focusAfterRemoval", () => {
  it("the next action entry shown (it took the removed action's index), else the previous one", () => {
    expect(focusAfterRemoval(3, [0, 1, 2, 3, 4])).toBe(3);
    expect(focusAfterRemoval(3, [4, 0, 7])).toBe(4); // filtered log: the next one shown, in any order
    expect(focusAfterRemoval(3, [0, 1, 2])).toBe(2); // the last action removed
    expect(focusAfterRemoval(0, [2, 1])).toBe(1);
  });

  it("the log itself when it shows no action entry", () => {
    expect(focusAfterRemoval(3, [])).toBeNull();
  });
});
