/**
 * docs/api.md's rows of `World` and `Timeline` against the type declarations the package ships
 * (dist/index.d.ts, read with TypeScript's checker): every public member is named in its class's
 * row, a method with its parameters as the declarations name them, optional ones marked `?`
 * (`addLine(id, p1, p2, kind)`, `body(id, t?)`). Review of session 26: a program written from
 * api.md alone could not know addLine's arguments (the row listed the edits by name only), and
 * `Timeline.fromScene`'s options, `gx`, `gy` and `opt` were not there at all.
 */
import { readFileSync } from "node:fs";
import { join } from "node:path";
import ts from "typescript";
import { describe, expect, it } from "vitest";
import { enginePkg } from "./npmTools.js";

const doc = readFileSync(join(enginePkg, "docs/api.md"), "utf8");

/** The row of the table whose first cell is `name`. */
function row(name: string): string {
  const line = doc.split("\n").find((l) => l.startsWith(`| \`${name}\` |`));
  if (line === undefined) throw new Error(`api.md has no row for ${name}`);
  return line;
}

/** The public members of an exported class as api.md should write them: `name(a, b?)` or `name`. */
function members(className: string): string[] {
  const entry = join(enginePkg, "dist/index.d.ts");
  const program = ts.createProgram([entry], { noEmit: true, types: [] });
  const checker = program.getTypeChecker();
  const module = checker.getSymbolAtLocation(program.getSourceFile(entry) as ts.SourceFile) as ts.Symbol;
  let cls = checker.getExportsOfModule(module).find((e) => e.name === className) as ts.Symbol;
  if (cls.flags & ts.SymbolFlags.Alias) cls = checker.getAliasedSymbol(cls);
  const out: string[] = [];
  const add = (p: ts.Symbol, prefix: string): void => {
    const decl = p.valueDeclaration ?? p.declarations?.[0];
    const hidden = ts.ModifierFlags.Private | ts.ModifierFlags.Protected;
    if (p.name === "prototype" || (decl !== undefined && ts.getCombinedModifierFlags(decl) & hidden)) return;
    if ((p.flags & ts.SymbolFlags.Method) === 0) {
      out.push(`\`${p.name}\``);
      return;
    }
    const [sig] = checker.getSignaturesOfType(checker.getTypeOfSymbol(p), ts.SignatureKind.Call);
    const params = (sig as ts.Signature).parameters.map((q) => {
      const d = q.valueDeclaration as ts.ParameterDeclaration;
      return `${q.name}${checker.isOptionalParameter(d) ? "?" : ""}`;
    });
    out.push(`\`${prefix}${p.name}(${params.join(", ")})\``);
  };
  for (const p of checker.getPropertiesOfType(checker.getDeclaredTypeOfSymbol(cls))) add(p, "");
  for (const p of checker.getPropertiesOfType(checker.getTypeOfSymbol(cls))) add(p, `${className}.`);
  return out;
}

describe("api.md names every public member of World and Timeline with its parameters", () => {
  it.each(["World", "Timeline"])("%s", (className) => {
    const all = members(className);
    expect(all.length).toBeGreaterThan(20);
    expect(all).toContain(className === "World" ? "`addLine(id, p1, p2, kind)`" : "`path(id, from?, to?)`");
    const text = row(className);
    expect(all.filter((m) => !text.includes(m))).toEqual([]);
  });
});

describe("api.md's BodyArrays order", () => {
  it('is JavaScript\'s default sort, as its examples say ("B" < "a", "b10" < "b9")', async () => {
    const line = doc.split("\n").find((l) => l.startsWith("| type `BodyArrays` |"));
    expect(line).toContain('`"B" < "a"`, `"b10" < "b9"`');
    const { World } = (await import(join(enginePkg, "dist/index.js"))) as typeof import("@chapgame/engine");
    const w = new World({ g: 0 });
    ["b9", "a", "B", "b10"].forEach((id, i) => {
      w.addBody(id, { x: 3 * i, y: 0, r: 1, m: 1 });
    });
    expect(w.bodyArrays().ids).toEqual(["B", "a", "b10", "b9"]);
    expect(w.bodies().map((b) => b.id)).toEqual(["B", "a", "b10", "b9"]);
  });
});

describe("api.md's World counts", () => {
  it("is live, as the EventCounts row says: a copy keeps the snapshot", async () => {
    const line = doc.split("\n").find((l) => l.startsWith("| type `EventCounts` |"));
    expect(line).toContain("one live, read-only object");
    const { World } = (await import(join(enginePkg, "dist/index.js"))) as typeof import("@chapgame/engine");
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody("b", { x: 5, y: 0, r: 1, m: 1 });
    const live = w.counts;
    const copy = { ...w.counts };
    w.advance({});
    expect([live.bodyBody, copy.bodyBody]).toEqual([1, 0]);
  });
});
