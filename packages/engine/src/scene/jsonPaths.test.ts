import { describe, expect, it } from "vitest";
import { type JsonToken, walkJson } from "./jsonPaths.js";

function tokens(text: string): JsonToken[] {
  const out: JsonToken[] = [];
  walkJson(text, (t) => {
    // path and literal are read during the visit
    out.push(
      t.kind === "key"
        ? { kind: t.kind, path: t.path, key: t.key, pos: t.pos, repeated: t.repeated }
        : { kind: t.kind, path: t.path, literal: t.literal, pos: t.pos, end: t.end },
    );
    return undefined;
  });
  return out;
}

describe("walkJson", () => {
  it("visits keys and numbers in text order with their paths, skipping strings and literals", () => {
    const text = '{"a": [1, {"b": -2.5e3}], "s": "3, 4", "t": true, "a": 5}';
    expect(tokens(text).map((t) => [t.kind, t.path, t.kind === "key" ? t.key : t.literal])).toEqual([
      ["key", "a", "a"],
      ["number", "a[0]", "1"],
      ["key", "a[1].b", "b"],
      ["number", "a[1].b", "-2.5e3"],
      ["key", "s", "s"],
      ["key", "t", "t"],
      ["key", "a", "a"],
      ["number", "a", "5"],
    ]);
    expect(tokens(text).filter((t) => t.kind === "key" && t.repeated)).toHaveLength(1);
  });

  it("stops at the first visit that returns a value", () => {
    let seen = 0;
    const r = walkJson("[1, 2, 3]", (t) => {
      seen++;
      return t.kind === "number" && t.literal === "2" ? t.path : undefined;
    });
    expect([r, seen]).toEqual(["[1]", 2]);
  });

  it("gives a number at the top level the empty path", () => {
    expect(tokens("42")).toEqual([{ kind: "number", path: "", literal: "42", pos: 0, end: 2 }]);
  });
});
