// The audit lexer (sourceText.ts): what it blanks, what it keeps, and that line numbers survive.
import { describe, expect, it } from "vitest";
import { stripCommentsAndStrings as strip } from "./sourceText.js";

describe("stripCommentsAndStrings", () => {
  it("blanks comments and keeps the code and the newlines", () => {
    const src = "a = 1; // Math.pow\n/* Date.now()\n */ b = Math.sqrt(2);";
    const out = strip(src);
    expect(out.length).toBe(src.length);
    expect(out.split("\n").length).toBe(3);
    expect(out).not.toContain("pow");
    expect(out).not.toContain("Date");
    expect(out).toContain("Math.sqrt(2)");
  });

  it("blanks the text of strings, with escapes", () => {
    const out = strip(`f("Math.pow \\" x", 'Date \\' y'); g(3 ** 2);`);
    expect(out).not.toContain("pow");
    expect(out).not.toContain("Date");
    expect(out).toContain("g(3 ** 2)");
  });

  it("keeps code inside a template's placeholders, nested, and blanks its text", () => {
    const open = "$" + "{"; // a placeholder's opening, spelled so that the linter sees no slip
    const out = strip(
      `const s = \`Math.exp ${open}Math.pow(a, { k: \`in ${open}Date.now()}\` }.k)} tail\`; h();`,
    );
    expect(out).not.toContain("exp");
    expect(out).not.toContain("tail");
    expect(out).not.toContain(" in ");
    expect(out).toContain("Math.pow(a, { k:");
    expect(out).toContain("Date.now()");
    expect(out).toContain("h();");
  });

  it("blanks regular-expression literals but not divisions", () => {
    const out = strip("const r = /Math\\.exp[/]x/g; const q = a / b / c; return /Date/.test(s);");
    expect(out).not.toContain("exp");
    expect(out).not.toContain("Date");
    expect(out).toContain("a / b / c");
  });
});
