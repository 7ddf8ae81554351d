// parseScene on the JSON text itself: a byte order mark, syntax errors with their line and column,
// duplicate keys, control characters, truncation, NaN/Infinity/undefined, and number literals a
// double cannot hold (beyond the largest double, below the smallest).
import { describe, expect, it } from "vitest";
import { parseScene } from "./parse.js";
import { base, disc, refused } from "./testSupport.js";

describe("parseScene on broken JSON", () => {
  it("reads a file that starts with a byte order mark (Windows editors write one; it was 'invalid JSON')", () => {
    const s = parseScene(`\uFEFF${base([disc("a", 0)])}`);
    expect(s.actions).toHaveLength(1);
  });
  it("says the line and column when the JSON parser gives a position (a 5,000-line file had only 'position 73')", () => {
    const text = '{"format":"chapgame","version":1,\n"actions":[\n{"time":0,"type":"addBody" "id":"a"}]}';
    const e = refused(text);
    expect(e.path).toBe("json");
    expect(e.message).toMatch(/^json: invalid JSON at line 3, column 28 \(/);
  });
  it("refuses a duplicate key, naming it and where it is (JSON.parse silently kept the last value)", () => {
    const text = base([disc("a", 0)]).replace('"r":1', '"r":1,"r":2');
    const e = refused(text);
    expect(e.path).toBe("actions[0].r");
    expect(e.message).toMatch(/duplicate key "r" at line 1, column \d+/);
  });

  it("writes control characters of a binary file as escapes (raw bytes went to the terminal)", () => {
    const e = refused("\u007fELF\u0002\u0001\u0001\u0000\u0000");
    expect(e.path).toBe("json");
    expect(e.message).toMatch(/^json: invalid JSON/);
    expect(e.message).toContain("\\u007fELF\\u0002");
    expect(
      [...e.message].filter(
        (c) => c.charCodeAt(0) < 0x20 || (c.charCodeAt(0) >= 0x7f && c.charCodeAt(0) <= 0x9f),
      ),
    ).toEqual([]);
  });

  it("says the position once, in lines and columns (Chromium's V8 adds its own '(line 1 column 8)')", () => {
    const e = refused('{"a":1 "b":2}');
    expect(e.message).toBe(
      "json: invalid JSON at line 1, column 8 (Expected ',' or '}' after property value)",
    );
    expect(e.message).not.toMatch(/position/);
  });

  it("says an empty text is empty (review of session 25: 'at the end (line 1, column 1)')", () => {
    for (const text of ["", " \n\t"])
      expect(refused(text).message).toMatch(
        /^json: invalid JSON: the text is empty \(a scene is a JSON object, /,
      );
  });

  it("names a comma before a closing brace or bracket (JavaScript allows it, JSON does not)", () => {
    const obj = refused('{"format":"chapgame","version":1,"actions":[],\n }');
    expect(obj.message).toMatch(
      /^json: invalid JSON at line 2, column 2: JSON allows no comma before \} \(remove the last comma\) \(/,
    );
    const arr = refused('{"format":"chapgame","version":1,"actions":[1,2, ]}');
    expect(arr.message).toMatch(
      /at line 1, column 50: JSON allows no comma before \] \(remove the last comma\)/,
    );
    // a closing brace after something else is not this slip
    expect(refused('{"a":1 }}').message).not.toMatch(/comma/);
  });

  it("says where a truncated text stops (the parser gives no position: it said only 'Unexpected end')", () => {
    const e = refused('{"format":"chapgame",\n"version":1,\n"actions":[');
    expect(e.path).toBe("json");
    expect(e.message).toMatch(
      /^json: invalid JSON at the end \(line 3, column 12\): the text stops early \(/,
    );
  });
});

describe("parseScene on values JSON does not have", () => {
  it("says where a NaN, Infinity or undefined is and what to write instead (V8 gave no position)", () => {
    const text = base([disc("a", 0)]).replace('"r":1', '"r":NaN');
    const col = text.indexOf("NaN") + 1;
    expect(refused(text).message).toMatch(
      new RegExp(
        `^json: invalid JSON at line 1, column ${col}: JSON has no NaN \\(write a finite number\\) \\(`,
      ),
    );
    const inf = `{\n "format": "chapgame", "version": 1, "g": -Infinity, "actions": []}`;
    expect(refused(inf).message).toMatch(/^json: invalid JSON at line 2, column 44: JSON has no Infinity \(/);
    const undef = '{"format": "chapgame", "version": 1, "meta": undefined, "actions": []}';
    expect(refused(undef).message).toMatch(
      /at line 1, column 46: JSON has no undefined \(leave the field out\)/,
    );
  });
});

describe("parseScene on number literals a double cannot hold", () => {
  it('refuses "m": 1e999 (JSON.parse read it as an infinite mass), naming the field and saying to write "Infinity"', () => {
    const text = base([disc("a", 0)]).replace('"m":1', '"m":1e999');
    const col = text.indexOf("1e999") + 1;
    const e = refused(text);
    expect(e.path).toBe("actions[0].m");
    expect(e.message).toBe(
      `actions[0].m: the number 1e999 at line 1, column ${col} is beyond the largest double (about 1.8e308): JSON would read it as Infinity; for an immovable body (an infinite mass) write the string "Infinity"; otherwise write a finite number`,
    );
    // the string form is the infinite mass
    expect(parseScene(base([disc("a", 0, { m: "Infinity" })])).actions[0]).toMatchObject({ m: Infinity });
  });

  it("refuses an overflowing literal anywhere: a coordinate, an array element, g, meta", () => {
    const cases: [string, string][] = [
      [base([disc("a", 0)]).replace('"x":0', '"x":-2e308'), "actions[0].x"],
      [base([disc("a", 0, { v: [1, 0] })]).replace('"v":[1,0]', '"v":[1,1E+400]'), "actions[0].v[1]"],
      [base([], { g: 1 }).replace('"g":1', '"g":1e309'), "g"],
      [base([], { meta: { zoom: [1, 2] } }).replace("[1,2]", "[1,9e999]"), "meta.zoom[1]"],
      [base([disc("a", 0)]).replace('"m":1', `"m":1${"0".repeat(400)}`), "actions[0].m"],
    ];
    for (const [text, path] of cases) {
      const e = refused(text);
      expect(e.path, text).toBe(path);
      expect(e.reason).toMatch(/is beyond the largest double .*JSON would read it as -?Infinity; /);
    }
    expect(refused(cases[0]?.[0]).reason).toMatch(/read it as -Infinity; write a finite number$/);
  });

  it("accepts the largest doubles and long literals that stay in range", () => {
    const text = base([], { meta: { big: 1 } }).replace('"big":1', '"big":[1.7976931348623157e308, -1e308]');
    expect(parseScene(text).meta).toEqual({ big: [1.7976931348623157e308, -1e308] });
  });

  it("explains a radius written 1e-999 (it reads as 0): the literal and why, not only 'must be positive'", () => {
    const e = refused(base([disc("a", 0)]).replace('"r":1', '"r":1e-999'));
    expect(e.message).toBe(
      "actions[0].r: must be a positive finite number (the file writes 1e-999, below the smallest double (about 5e-324): JSON reads it as 0)",
    );
    const neg = refused(base([disc("a", 0)]).replace('"m":1', '"m":-0.5e-400'));
    expect(neg.message).toMatch(/^actions\[0\]\.m: must be a positive .*\(the file writes -0\.5e-400, /);
    // an element of a vector: a segment whose ends read as equal
    const line = { time: 0, type: "addLine", id: "l", p1: [0, 0], p2: [7, 0], kind: "segment" };
    const same = refused(base([line]).replace('"p2":[7,0]', '"p2":[1e-999,0]'));
    expect(same.message).toMatch(/^actions\[0\]\.p2: must differ from p1 \(the file writes 1e-999, /);
    // a field that takes 0 keeps the value: 1e-999 is 0 there, as JSON reads it
    expect(parseScene(base([disc("a", 0)]).replace('"x":0', '"x":1e-999')).actions[0]).toMatchObject({
      x: 0,
    });
  });

  it("names a literal deep in meta by a shortened path, and a very long literal by its ends", () => {
    // Review of session 16: a 1e999 a million levels deep in meta gave a 3 MB message.
    const depth = 5000;
    const deep = `{"format":"chapgame","version":1,"meta":{"x":${"[".repeat(depth)}1e999${"]".repeat(depth)}},"actions":[]}`;
    const e = refused(deep);
    expect(e.message.length).toBeLessThan(600);
    expect(e.message).toMatch(
      /^meta\.x\[0\]\[0\].*…\(\d+ characters\)….*\[0\]: the number 1e999 at line 1, column \d+ is beyond/,
    );
    const long = `{"format":"chapgame","version":1,"actions":[{"time":0,"type":"addBody","id":"a","x":0,"y":0,"r":1,"m":1${"0".repeat(400)}}]}`;
    expect(() => parseScene(long)).toThrow(/^actions\[0\]\.m: the number 10{19}…0{12} at line 1/);
  });
});
