// Why the engine gives the same bits in Node and in every browser: its source uses only operations
// whose results ECMAScript specifies exactly. +, -, *, / and Math.sqrt are IEEE-754 correctly
// rounded; abs, min, max, floor, ceil, round, trunc, sign, fround, imul and clz32 are exact. The
// other Math functions (pow, exp, log, sin, atan2, hypot, cbrt, ...) and the ** operator are
// "implementation-approximated": two engines may differ in the last bit. The one use of ** allowed
// is 2 ** n with an integer n (a power of two, exactly representable, which every engine computes
// exactly). And no clock, randomness or host object: the results depend on the input alone.
//
// This test reads the engine's source (not its tests) and fails on anything else, naming the file
// and line. tests/e2e/engineInBrowser.test.ts checks the claim itself in Chromium.
import { readdirSync, readFileSync } from "node:fs";
import { join, relative } from "node:path";
import { fileURLToPath } from "node:url";
import { describe, expect, it } from "vitest";
import { stripCommentsAndStrings } from "./sourceText.js";

const SRC = fileURLToPath(new URL("../src", import.meta.url));

/**
 * Math functions whose results ECMAScript specifies exactly (no implementation approximation), and
 * Math's constants (PI, E, ...: each "the Number value for" its real, one double in every engine).
 */
const EXACT_MATH = new Set([
  "abs",
  "min",
  "max",
  "sqrt",
  "floor",
  "ceil",
  "round",
  "trunc",
  "sign",
  "fround",
  "imul",
  "clz32",
]);
const isExactMath = (name: string): boolean => EXACT_MATH.has(name) || /^[A-Z][A-Z0-9_]*$/.test(name);

/** Globals that read a clock, randomness, the host or the environment. */
const HOST =
  /(?<![.\w$])(Date|performance|crypto|setTimeout|setInterval|setImmediate|queueMicrotask|process|window|document|navigator|globalThis|require|Intl)\b/g;

function sourceFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) => {
    const path = join(dir, e.name);
    if (e.isDirectory()) return sourceFiles(path);
    const isSource = e.name.endsWith(".ts") && !e.name.endsWith(".test.ts") && e.name !== "testSupport.ts";
    return isSource ? [path] : [];
  });
}

/** "file:line: text" for every match of `pattern` in the code of `path` that `bad` accepts. */
function findings(path: string, pattern: RegExp, bad: (m: RegExpExecArray) => boolean): string[] {
  const code = stripCommentsAndStrings(readFileSync(path, "utf8"));
  const out: string[] = [];
  for (const m of code.matchAll(pattern)) {
    if (!bad(m)) continue;
    const line = code.slice(0, m.index).split("\n").length;
    out.push(`${relative(SRC, path)}:${line}: ${m[0]}`);
  }
  return out;
}

const files = sourceFiles(SRC);
/** The CLI (src/cli) reads files, arguments and the environment; it computes nothing itself. */
const library = files.filter((f) => !relative(SRC, f).startsWith("cli"));

describe("the engine's arithmetic is exactly specified by ECMAScript", () => {
  it("reads the whole source: every folder, and the simulation's core files", () => {
    const names = files.map((f) => relative(SRC, f));
    for (const f of ["sim/predictor.ts", "roots/realRoots.ts", "physics/response.ts", "timeline/index.ts"])
      expect(names).toContain(f);
    expect(files.length).toBeGreaterThan(60);
  });

  it("uses no Math function that engines may round differently", () => {
    const used = new Set<string>();
    const bad = files.flatMap((f) =>
      findings(f, /\bMath\.(\w+)/g, (m) => {
        used.add(m[1] as string);
        return !isExactMath(m[1] as string);
      }),
    );
    expect(bad).toEqual([]);
    // The scan sees the calls (it would pass vacuously on code it cannot read).
    expect(used).toContain("sqrt");
    expect(used).toContain("abs");
  });

  it("uses ** only for powers of two", () => {
    let seen = 0;
    const bad = files.flatMap((f) =>
      findings(f, /(\S+)\s*\*\*(?!=)/g, (m) => {
        seen++;
        return !/(^|[^\w.])2$/.test(m[1] as string);
      }),
    );
    expect(bad).toEqual([]);
    expect(seen).toBeGreaterThan(10);
  });

  it("reads no clock, randomness, host object or environment outside the CLI", () => {
    expect(library.flatMap((f) => findings(f, HOST, () => true))).toEqual([]);
    // The pattern does find them: the CLI uses process.
    expect(files.flatMap((f) => findings(f, HOST, () => true)).length).toBeGreaterThan(0);
  });
});
