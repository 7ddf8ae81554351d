import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { jsonErrorOffset } from "./jsonSyntax.js";

/** V8's offset for the error, when its message gives one (null when it does not). */
function v8Offset(text: string): number | null {
  try {
    JSON.parse(text);
    return -1;
  } catch (e) {
    const m = /position (\d+)/.exec((e as Error).message);
    if (m !== null) return Number(m[1]);
    return /end of JSON input/.test((e as Error).message) ? text.length : null;
  }
}

describe("jsonErrorOffset", () => {
  it("points at the character V8 names without a position (a scene with NaN got no line or column)", () => {
    const cases: [string, number][] = [
      ['{"a": NaN}', 6],
      ['{"a": Infinity}', 6],
      ['{"a": -Infinity}', 7],
      ['{"a": undefined}', 6],
      ['{"a": tru}', 9],
      ['{"b": {}, "a": tru}', 18],
      ["{'a': 1}", 1],
      ['{"a": 1} x', 9],
      ['{"a": "x\\q"}', 9],
    ];
    for (const [text, offset] of cases) expect([text, jsonErrorOffset(text)]).toEqual([text, offset]);
  });

  it("gives the end of the text when it stops early, and -1 for valid JSON", () => {
    for (const text of ["", "  ", '{"a": [1, 2', '{"a"', '"abc', "-", "1e", '{"a": "\\u12'])
      expect([text, jsonErrorOffset(text)]).toEqual([text, text.length]);
    for (const text of [
      "0",
      " -0.5e+3 ",
      '{"a": [true, false, null, {}, []], "b": "\\u00e9\\n"}',
      "[[[[[]]]]]",
    ])
      expect([text, jsonErrorOffset(text)]).toEqual([text, -1]);
  });

  it("handles nesting far deeper than the call stack", () => {
    const deep = `${"[".repeat(200_000)}${"]".repeat(200_000)}`;
    expect(jsonErrorOffset(deep)).toBe(-1);
    expect(jsonErrorOffset(`${deep.slice(0, -1)}}`)).toBe(deep.length - 1);
  });

  it("agrees with JSON.parse on random damaged JSON: valid exactly when it parses, and at V8's position when V8 gives one (property)", () => {
    const seed = seedFor("jsonErrorOffset property", 20261123);
    const alphabet = fc.constantFrom(...'{}[]",:0123456789-+.eEtrufalsnNI \n\\/u'.split(""));
    const edit = fc.record({
      at: fc.nat(),
      kind: fc.constantFrom("insert", "delete", "replace"),
      c: alphabet,
    });
    fc.assert(
      fc.property(fc.jsonValue(), fc.array(edit, { maxLength: 3 }), fc.boolean(), (value, edits, pretty) => {
        let text = JSON.stringify(value, null, pretty ? 2 : undefined) ?? "null";
        for (const e of edits) {
          const at = text.length === 0 ? 0 : e.at % (text.length + 1);
          if (e.kind === "insert") text = text.slice(0, at) + e.c + text.slice(at);
          else if (e.kind === "delete") text = text.slice(0, at) + text.slice(at + 1);
          else text = text.slice(0, at) + e.c + text.slice(at + 1);
        }
        const ours = jsonErrorOffset(text);
        const v8 = v8Offset(text);
        expect(ours === -1).toBe(v8 === -1);
        if (v8 !== null) expect(ours).toBe(v8);
        if (ours !== -1) expect(ours).toBeLessThanOrEqual(text.length);
      }),
      { seed, numRuns: 3000 },
    );
  });
});
