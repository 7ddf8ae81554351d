// roundingNote: a time typed with more digits than a double holds is noted when it reads as a
// double that prints differently; one that prints as typed is not.
import { describe, expect, it } from "vitest";
import { exactDecimal, roundingNote } from "./rounding.js";

describe("exactDecimal", () => {
  it("writes the same value the same way, whatever the form", () => {
    for (const same of ["12.5", "12.50", "012.5", "1.25e1", "125e-1", "+12.5", "0.125E2"])
      expect(exactDecimal(same), same).toBe("125e-1");
    expect(exactDecimal("1000")).toBe("1e3");
    expect(exactDecimal("1e+21")).toBe("1e21");
    expect(exactDecimal("0")).toBe("0e0");
    expect(exactDecimal("0.000")).toBe("0e0");
    expect(exactDecimal(".5")).toBe("5e-1");
    expect(exactDecimal("3.")).toBe("3e0");
    expect(exactDecimal("abc")).toBeNull();
    expect(exactDecimal(".")).toBeNull();
  });
});

describe("roundingNote", () => {
  it("notes a time that reads as a different double: 0.99999999999999999999999 is 1", () => {
    // Review of session 31: `state --at 0.99999999999999999999999` silently printed the state at 1.
    expect(roundingNote("--at", "0.99999999999999999999999", Number("0.99999999999999999999999"))).toBe(
      "--at 0.99999999999999999999999 is read as 1 (the nearest double)",
    );
    expect(roundingNote("--to", "0.3000000000000000444", 0.30000000000000004)).toBe(
      "--to 0.3000000000000000444 is read as 0.30000000000000004 (the nearest double)",
    );
  });

  it("says nothing of a time that prints as typed, in any form", () => {
    for (const t of ["0.1", "12.50", "1e3", "1e30", "0.30000000000000004", "5e-324", "0", "7"])
      expect(roundingNote("--at", t, Number(t)), t).toBeNull();
  });
});
