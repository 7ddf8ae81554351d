import { describe, expect, it } from "vitest";
import { firstDuplicateKey } from "./jsonDuplicates.js";

describe("firstDuplicateKey", () => {
  it("finds none in a text without repeats, nested or not", () => {
    expect(firstDuplicateKey('{"a":1,"b":{"a":2,"c":[{"a":3},{"a":4}]},"s":"a\\"b"}')).toBeNull();
    expect(firstDuplicateKey("[1, 2, 3]")).toBeNull();
    expect(firstDuplicateKey('"just a string"')).toBeNull();
  });

  it("names the repeated key with its path, line and column", () => {
    const text = '{\n  "actions": [\n    {"id": "a"},\n    {"id": "b", "r": 1, "r": 2}\n  ]\n}';
    expect(firstDuplicateKey(text)).toEqual({ path: "actions[1].r", key: "r", line: 4, column: 25 });
  });

  it("counts lines ended by \\n, \\r\\n or a lone \\r (old Mac files) alike", () => {
    for (const eol of ["\n", "\r\n", "\r"])
      expect(firstDuplicateKey(`{${eol}"a": 1,${eol}  "a": 2${eol}}`), JSON.stringify(eol)).toMatchObject({
        line: 3,
        column: 3,
      });
  });

  it("compares keys after unescaping, as JSON.parse does", () => {
    expect(firstDuplicateKey('{"g": 1, "\\u0067": 2}')).toMatchObject({ path: "g", key: "g" });
  });

  it("does not take string values, or keys of sibling objects, for repeats", () => {
    expect(firstDuplicateKey('{"a": "b", "b": "a"}')).toBeNull();
    expect(firstDuplicateKey('[{"x": 1}, {"x": 2}]')).toBeNull();
    expect(firstDuplicateKey('{"a": {"x": 1}, "b": {"x": 2}}')).toBeNull();
  });

  it("finds a repeat after a nested object closes, at the top level", () => {
    expect(firstDuplicateKey('{"meta": {"k": [1, {"z": 0}]}, "meta": {}}')).toMatchObject({ path: "meta" });
  });

  it("handles deep nesting without recursion", () => {
    const deep = `${"[".repeat(100000)}${"]".repeat(100000)}`;
    expect(firstDuplicateKey(deep)).toBeNull();
  });
});
