import { describe, expect, it } from "vitest";
import { isWidthMessage, messageAfterWidth, narrowedWidth, refusedWidth } from "./zoomWidthMessages";

describe("window width field messages", () => {
  it("a width narrower than the smallest window there names that width and why", () => {
    expect(narrowedWidth("1e-300", 1e-300, 3.3, 10)).toEqual({
      text: 'Window width (s): "1e-300" is narrower than the smallest window, 1e-9 s (a billionth of a second); the window is widened to that',
      tone: "info",
    });
    expect(narrowedWidth("1e-6", 1e-6, 1.23456789e8, 2e8)?.text).toBe(
      'Window width (s): "1e-6" is narrower than the smallest window at t = 1.23457e+8 s, 0.000123457 s' +
        " (the time's precision: a window spans at least 1e-12 of its time); the window is widened to that",
    );
    // a width the window can have: no note
    expect(narrowedWidth("1e-9", 1e-9, 3.3, 10)).toBeNull();
    expect(narrowedWidth("0.002", 0.002, 1e9, 1e9)).toBeNull();
  });

  it("an applied width replaces the field's own message (by the note, or none), not another one", () => {
    const refused = { text: refusedWidth("0"), tone: "error" as const };
    expect(refused.text).toBe("Window width (s): must be a positive number of seconds (got 0)");
    expect(isWidthMessage(refused)).toBe(true);
    expect(messageAfterWidth(refused, "4", 4, 5, 10)).toBeNull();
    const note = narrowedWidth("1e-12", 1e-12, 5, 10);
    expect(isWidthMessage(note)).toBe(true);
    expect(messageAfterWidth(refused, "1e-12", 1e-12, 5, 10)).toEqual(note);
    expect(messageAfterWidth(note, "2", 2, 5, 10)).toBeNull();
    const other = { text: "Time (s): must be 0 or later (got -1)", tone: "error" as const };
    expect(isWidthMessage(other)).toBe(false);
    expect(messageAfterWidth(other, "2", 2, 5, 10)).toBe(other);
    expect(messageAfterWidth(null, "2", 2, 5, 10)).toBeNull();
  });
});
