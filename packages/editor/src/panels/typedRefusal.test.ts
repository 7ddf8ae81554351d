import { describe, expect, it } from "vitest";
import { notANumber, refusedTyped, typedGiven } from "./typedRefusal";

describe("typedGiven", () => {
  it("names a number as it was typed, without quotes, as the engine names a number", () => {
    expect(typedGiven(" -3 ")).toBe("-3");
    expect(typedGiven("1e400")).toBe("1e400");
    expect(typedGiven("∞")).toBe("∞");
    expect(typedGiven(".5")).toBe(".5");
  });

  it("quotes other text with JSON escapes, the empty text included", () => {
    expect(typedGiven("abc")).toBe('"abc"');
    expect(typedGiven("  ")).toBe('""');
    expect(typedGiven('1,5 "m"')).toBe('"1,5 \\"m\\""');
    expect(typedGiven("3 s")).toBe('"3 s"');
  });

  it("cuts text longer than 40 characters, as the engine cuts a string", () => {
    const long = "x".repeat(41);
    expect(typedGiven(long)).toBe(`"${"x".repeat(40)}…"`);
    expect(typedGiven("y".repeat(40))).toBe(`"${"y".repeat(40)}"`);
  });
});

describe("refusedTyped and notANumber", () => {
  it("read as the engine's refusals: label, reason, (got …), then the explanation", () => {
    expect(refusedTyped("Time (s)", "must be 0 or later", "-3")).toBe(
      "Time (s): must be 0 or later (got -3)",
    );
    expect(refusedTyped("Speed", "must be a finite number", "fast", "a negative speed plays backwards")).toBe(
      'Speed: must be a finite number (got "fast"): a negative speed plays backwards',
    );
    expect(notANumber("ball x", " abc ")).toBe('ball x: must be a number (got "abc")');
  });
});
