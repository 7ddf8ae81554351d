import { describe, expect, it } from "vitest";
import { formatNumber, parseNumber } from "./EditableCell";

describe("cell numbers", () => {
  it("parses plain numbers, exponents and infinity, refuses anything else", () => {
    expect(parseNumber(" 12.5 ")).toBe(12.5);
    expect(parseNumber("-3e2")).toBe(-300);
    expect(parseNumber("∞")).toBe(Number.POSITIVE_INFINITY);
    expect(parseNumber("Infinity")).toBe(Number.POSITIVE_INFINITY);
    expect(parseNumber("")).toBeNull();
    expect(parseNumber("12abc")).toBeNull();
    expect(parseNumber("NaN")).toBeNull();
  });

  it("formats with six significant digits", () => {
    expect(formatNumber(1 / 3)).toBe("0.333333");
    expect(formatNumber(1234567)).toBe("1234570");
    expect(formatNumber(-0)).toBe("0");
    expect(formatNumber(Number.POSITIVE_INFINITY)).toBe("∞");
  });
});
