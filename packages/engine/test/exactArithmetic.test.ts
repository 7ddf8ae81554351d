// Why the engine gives the same bits in Node and in every browser: its source uses only operations
// whose results ECMAScript specifies exactly. +, -, *, / and Math.sqrt are IEEE-754 correctly
// rounded; abs, min, max, floor, ceil, round, trunc, sign, fround, imul and clz32 are exact. The
// other Math functions (pow, exp, log, sin, atan2, hypot, cbrt, ...) and ** are left by the
// specification to each engine ("implementation-approximated"): two engines may differ in the last
// bit. The one use of ** allowed is a constant power of two, 2 ** n with an integer literal n: the
// specification leaves it to the engine too, but the value is exactly representable and every
// engine computes it exactly (a power of two computed at run time goes through roots/pow2.ts,
// which builds it from its bits). And no clock, randomness, locale or host object: the results
// depend on the input alone.
//
// This test parses the engine's source (not its tests) with TypeScript's parser and fails on
// anything else, naming the file and line. tests/e2e/engineInBrowser.test.ts checks the claim
// itself in Chromium.
import { readdirSync, readFileSync } from "node:fs";
import { join, relative } from "node:path";
import { fileURLToPath } from "node:url";
import ts from "typescript";
import { describe, expect, it } from "vitest";

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

/** Globals that read a clock, randomness, the garbage collector, the host or the environment. */
const HOST = new Set([
  "Date",
  "performance",
  "crypto",
  "setTimeout",
  "setInterval",
  "setImmediate",
  "queueMicrotask",
  "process",
  "window",
  "document",
  "navigator",
  "globalThis",
  "require",
  "Intl",
  "WeakRef",
  "FinalizationRegistry",
]);
/** Methods whose results depend on the locale. */
const LOCALE = /^(localeCompare|toLocale\w*)$/;

function sourceFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) => {
    const path = join(dir, e.name);
    if (e.isDirectory()) return sourceFiles(path);
    const isSource = e.name.endsWith(".ts") && !e.name.endsWith(".test.ts") && e.name !== "testSupport.ts";
    return isSource ? [path] : [];
  });
}

interface Findings {
  /** "file:line: text" of each use of Math other than an exactly specified member. */
  math: string[];
  /** ... of each ** or **= other than 2 ** <integer literal>. */
  power: string[];
  /** ... of each host global or locale-dependent method. */
  host: string[];
  /** Counts of what the walk saw (so that a walk that sees nothing cannot pass). */
  seen: { math: number; power: number; host: number };
}

/** Whether identifier n names a property or member (o.n, { n: v }, class { n() {} }), not a variable. */
function isPropertyName(n: ts.Identifier): boolean {
  const p = n.parent;
  const named =
    ts.isPropertyAccessExpression(p) ||
    ts.isPropertyAssignment(p) ||
    ts.isMethodDeclaration(p) ||
    ts.isPropertyDeclaration(p) ||
    ts.isGetAccessorDeclaration(p) ||
    ts.isSetAccessorDeclaration(p) ||
    ts.isPropertySignature(p) ||
    ts.isMethodSignature(p) ||
    ts.isEnumMember(p);
  return named && p.name === n;
}

/** An integer literal, possibly negated: the exponent of an allowed power of two. */
function isIntegerLiteral(e: ts.Expression): boolean {
  if (ts.isPrefixUnaryExpression(e) && e.operator === ts.SyntaxKind.MinusToken)
    return isIntegerLiteral(e.operand);
  return ts.isNumericLiteral(e) && Number.isInteger(Number(e.text));
}

/** The findings in one file's source text (`name` labels them). */
function auditText(name: string, text: string): Findings {
  const file = ts.createSourceFile(name, text, ts.ScriptTarget.Latest, true);
  const f: Findings = { math: [], power: [], host: [], seen: { math: 0, power: 0, host: 0 } };
  const where = (n: ts.Node): string =>
    `${name}:${file.getLineAndCharacterOfPosition(n.getStart()).line + 1}: ${n.getText().slice(0, 60)}`;
  const visit = (n: ts.Node): void => {
    if (ts.isIdentifier(n)) {
      const parent = n.parent;
      const isName = isPropertyName(n);
      if (n.text === "Math" && !isName) {
        f.seen.math++;
        // Only Math.<exact member>: aliases, destructuring, Math[...] and Math?. are refused.
        const ok =
          ts.isPropertyAccessExpression(parent) &&
          parent.expression === n &&
          !parent.questionDotToken &&
          isExactMath(parent.name.text);
        if (!ok) f.math.push(where(parent));
      }
      if (HOST.has(n.text) && !isName) {
        f.seen.host++;
        f.host.push(where(n));
      }
      if (LOCALE.test(n.text) && isName) f.host.push(where(parent));
    }
    if (ts.isBinaryExpression(n)) {
      const op = n.operatorToken.kind;
      if (op === ts.SyntaxKind.AsteriskAsteriskToken || op === ts.SyntaxKind.AsteriskAsteriskEqualsToken) {
        f.seen.power++;
        const ok =
          op === ts.SyntaxKind.AsteriskAsteriskToken &&
          ts.isNumericLiteral(n.left) &&
          n.left.text === "2" &&
          isIntegerLiteral(n.right);
        if (!ok) f.power.push(where(n));
      }
    }
    ts.forEachChild(n, visit);
  };
  visit(file);
  return f;
}

const files = sourceFiles(SRC);
const audits = new Map(
  files.map((f) => {
    const name = relative(SRC, f);
    return [name, auditText(name, readFileSync(f, "utf8"))];
  }),
);
/** The CLI (src/cli) reads files, arguments and the environment; it computes nothing itself. */
const inLibrary = (name: string): boolean => !name.startsWith("cli");
const all = (pick: (f: Findings) => string[], keep: (name: string) => boolean = () => true): string[] =>
  [...audits].filter(([name]) => keep(name)).flatMap(([, f]) => pick(f));
const count = (pick: (f: Findings) => number): number =>
  [...audits.values()].reduce((s, f) => s + pick(f), 0);

describe("the engine's arithmetic is exactly specified by ECMAScript", () => {
  it("parses the whole source: every folder, and the simulation's core files", () => {
    const names = [...audits.keys()];
    for (const f of ["sim/predictor.ts", "roots/realRoots.ts", "physics/response.ts", "timeline/index.ts"])
      expect(names).toContain(f);
    expect(files.length).toBeGreaterThan(60);
  });

  it("uses Math only for the functions engines cannot round differently", () => {
    expect(all((f) => f.math)).toEqual([]);
    expect(count((f) => f.seen.math)).toBeGreaterThan(100);
  });

  it("uses ** only for constant powers of two", () => {
    expect(all((f) => f.power)).toEqual([]);
    expect(count((f) => f.seen.power)).toBeGreaterThan(10);
  });

  it("reads no clock, randomness, locale, host object or environment outside the CLI", () => {
    expect(all((f) => f.host, inLibrary)).toEqual([]);
    // The walk does find them: the CLI uses process.
    expect(all((f) => f.host).length).toBeGreaterThan(0);
  });
});

describe("the audit itself", () => {
  const flagged = (code: string): string[] => {
    const f = auditText("snippet.ts", code);
    return [...f.math, ...f.power, ...f.host];
  };

  it("flags what could slip past a text search (review of session 12)", () => {
    for (const code of [
      "v **= 0.5;",
      "const a = 2 ** 0.5;",
      "const b = x ** 2;",
      "const c = 2 ** k;",
      "const { exp } = Math;",
      "const M = Math; M.exp(1);",
      "Math?.exp(1);",
      "Math\n  .exp(1);",
      'Math["exp"](1);',
      "const d = i++ / 2 + Math.exp(z) / 3;",
      "const e = o.in / 2 + Math.exp(1) / 3;",
      "if (ok) /`/.test(s);\nconst f = Math.exp(1);",
      "const g = Date.now();",
      "const h = new WeakRef(o);",
      "const i = a.localeCompare(b);",
      "const j = n.toLocaleString();",
    ])
      expect(flagged(code), code).not.toEqual([]);
  });

  it("passes exact arithmetic, constant powers of two, and names that only look like hosts", () => {
    for (const code of [
      "const a = Math.sqrt(x) + Math.abs(y) * Math.PI;",
      "const b = 2 ** -53 + 2 ** 1023;",
      `const c = \`Math.exp ${"$"}{Math.max(1, 2)}\`; // Math.pow(2, 0.5), Date.now()`,
      'const d = "Math.exp(1) and process.exit()";',
      "const e = { process: 1, Date: 2 }; e.process + obj.Date;",
      "class K { process(): void {} }",
    ])
      expect(flagged(code), code).toEqual([]);
  });
});
