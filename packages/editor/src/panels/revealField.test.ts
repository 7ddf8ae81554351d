import { describe, expect, it } from "vitest";
import { revealsField } from "./revealField";

describe("revealsField", () => {
  it("reveals the field for a key that types, deletes, moves the caret or commits", () => {
    for (const key of ["a", "2", "-", "Backspace", "Delete", "ArrowLeft", "Enter", "Escape", " "])
      expect(revealsField(key), key).toBe(true);
  });

  it("reveals nothing for a modifier pressed alone (held for a capital or a shortcut)", () => {
    for (const key of ["Shift", "Control", "Alt", "Meta", "CapsLock"])
      expect(revealsField(key), key).toBe(false);
  });
});
