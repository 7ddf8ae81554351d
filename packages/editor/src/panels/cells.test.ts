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

  it("writes numbers of 10^7 and more with an exponent (a mass of 10^12 was 13 digits wide)", () => {
    expect(formatNumber(1e12)).toBe("1e+12");
    expect(formatNumber(-1234567890)).toBe("-1.23457e+9");
    expect(formatNumber(9999990)).toBe("9999990");
    for (const x of [1e12, 1234567890, 6.02e23])
      expect(parseNumber(formatNumber(x))).toBe(Number(x.toPrecision(6)));
  });
});
