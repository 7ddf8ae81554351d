/**
 * docs/api.md is "the list of everything src/index.ts exports": every exported value and type is
 * named there in backticks, and the counts its first paragraph gives are the entry's (audit of
 * session 23: it said 81 values after the ZENO_TRAP_* tolerances made 87).
 */
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import ts from "typescript";
import { describe, expect, it } from "vitest";
import * as api from "../src/index.js";

const doc = readFileSync(fileURLToPath(new URL("../docs/api.md", import.meta.url)), "utf8");

/** The names src/index.ts exports only as types (TypeScript's checker on the source). */
function typeOnlyExports(): string[] {
  const entry = fileURLToPath(new URL("../src/index.ts", import.meta.url));
  const program = ts.createProgram([entry], { noEmit: true, types: [] });
  const checker = program.getTypeChecker();
  const module = checker.getSymbolAtLocation(program.getSourceFile(entry) as ts.SourceFile) as ts.Symbol;
  return checker
    .getExportsOfModule(module)
    .filter((e) => {
      const s = e.flags & ts.SymbolFlags.Alias ? checker.getAliasedSymbol(e) : e;
      return (s.flags & ts.SymbolFlags.Value) === 0;
    })
    .map((e) => e.name);
}

/** Whether api.md names `name` as code: `name`, `name(…)`, `name<…>` or type `name`. */
const named = (name: string): boolean => new RegExp(`\`${name}[\`(<]`).test(doc);

describe("docs/api.md lists every export of the entry", () => {
  const values = Object.keys(api);
  const types = typeOnlyExports();

  it("names every exported value and type", () => {
    expect(values.filter((n) => !named(n))).toEqual([]);
    expect(types.filter((n) => !doc.includes(`type \`${n}\``) && !named(n))).toEqual([]);
    expect(types).toContain("SceneFile");
  });

  it("gives the entry's counts of values and types", () => {
    const counts = /: (\d+) values, the output of[\s\S]*?and (\d+) types\./.exec(doc);
    expect(counts, "api.md states the counts").not.toBeNull();
    expect([Number(counts?.[1]), Number(counts?.[2])]).toEqual([values.length, types.length]);
  });
});
