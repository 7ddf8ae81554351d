import { describe, expect, it } from "vitest";
import { afterFieldApplied, isFieldMessage } from "./fieldMessages";

describe("a field's own messages", () => {
  it("are those starting with its label; applying a value drops them and keeps any other", () => {
    const own = { text: "Time (s): must be 0 or later (got -3)", tone: "error" as const };
    const other = {
      text: "Window width (s): must be a positive number of seconds (got 0)",
      tone: "error" as const,
    };
    expect(isFieldMessage(own, "Time (s)")).toBe(true);
    expect(isFieldMessage(other, "Time (s)")).toBe(false);
    expect(isFieldMessage({ text: "Time (s) of the event", tone: "info" }, "Time (s)")).toBe(false);
    expect(isFieldMessage(null, "Time (s)")).toBe(false);
    expect(afterFieldApplied(own, "Time (s)")).toBeNull();
    expect(afterFieldApplied(other, "Time (s)")).toBe(other);
    expect(afterFieldApplied(null, "Time (s)")).toBeNull();
  });
});
