import { describe, expect, it } from "vitest";
import { ChapgameError } from "../sim/errors.js";
import { SceneError } from "./errors.js";
import { parseScene } from "./parse.js";

const base = (actions: unknown[], extra: Record<string, unknown> = {}) =>
  JSON.stringify({ format: "chapgame", version: 1, actions, ...extra });
const disc = (id: string, x: number, more: Record<string, unknown> = {}) => ({
  time: 0,
  type: "addBody",
  id,
  x,
  y: 0,
  r: 1,
  m: 1,
  ...more,
});

function refused(input: unknown): SceneError {
  try {
    parseScene(input);
  } catch (e) {
    expect(e).toBeInstanceOf(SceneError);
    return e as SceneError;
  }
  throw new Error("parseScene accepted invalid input");
}

describe("parseScene accepts and normalizes", () => {
  it("fills defaults: g 9.81, gravity [0,0], mu 0, v [0,0]", () => {
    const s = parseScene(base([disc("a", 0)]));
    expect(s.g).toBe(9.81);
    expect(s.gravity).toEqual([0, 0]);
    expect(s.actions[0]).toEqual({
      time: 0,
      type: "addBody",
      id: "a",
      x: 0,
      y: 0,
      r: 1,
      m: 1,
      mu: 0,
      v: [0, 0],
    });
  });
  it('reads "Infinity" as an infinite mass, from text and from objects', () => {
    expect(parseScene(base([disc("a", 0, { m: "Infinity" })])).actions[0]).toMatchObject({ m: Infinity });
    const obj = { format: "chapgame", version: 1, actions: [disc("a", 0, { m: Infinity })] };
    expect(parseScene(obj).actions[0]).toMatchObject({ m: Infinity });
  });
  it("parses the issue's example scene", () => {
    const s = parseScene(`{ "format": "chapgame", "version": 1, "g": 9.81, "gravity": [0, 0],
      "actions": [
        { "time": 0, "type": "addBody", "id": "a", "x": 350, "y": 200, "r": 100, "m": 10, "mu": 1, "v": [0, 0] },
        { "time": 0, "type": "addLine", "id": "wall", "p1": [0, 0], "p2": [0, 500], "kind": "segment" },
        { "time": 0, "type": "addPoint", "id": "pin", "p": [10, 10] },
        { "time": 2.5, "type": "giveVelocity", "id": "a", "v": [-100, 0] } ] }`);
    expect(s.actions.map((a) => a.type)).toEqual(["addBody", "addLine", "addPoint", "giveVelocity"]);
  });
  it("allows touching bodies, re-adding a removed id, the same id for a body and a line", () => {
    expect(() =>
      parseScene(
        base([
          disc("a", 0),
          disc("b", 2),
          { time: 1, type: "removeBody", id: "a" },
          disc("a", 50, { time: 1 }),
          { time: 0, type: "addLine", id: "a", p1: [0, 10], p2: [1, 10], kind: "line" },
        ]),
      ),
    ).not.toThrow();
  });
  it("applies actions in time order, same time in file order", () => {
    // the give comes first in the file but at a later time: valid
    expect(() =>
      parseScene(base([{ time: 1, type: "giveVelocity", id: "a", v: [1, 0] }, disc("a", 0)])),
    ).not.toThrow();
  });
});

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

  it("says where a truncated text stops (the parser gives no position: it said only 'Unexpected end')", () => {
    const e = refused('{"format":"chapgame",\n"version":1,\n"actions":[');
    expect(e.path).toBe("json");
    expect(e.message).toMatch(
      /^json: invalid JSON at the end \(line 3, column 12\): the text stops early \(/,
    );
  });
});

describe("parseScene refuses, naming the path and the reason", () => {
  const cases: [string, unknown, string][] = [
    ["broken JSON", "{ nope", "json: invalid JSON"],
    ["not an object", "[1]", "scene: must be a JSON object"],
    ["wrong format", JSON.stringify({ format: "x", version: 1, actions: [] }), 'format: must be "chapgame"'],
    [
      "a newer version: said to come from a newer chapgame",
      JSON.stringify({ format: "chapgame", version: 2, actions: [] }),
      "version: unsupported version 2 (this reader knows 1): the file comes from a newer chapgame",
    ],
    [
      "a version that is no newer one (a string): no such claim",
      JSON.stringify({ format: "chapgame", version: "1", actions: [] }),
      'version: unsupported version "1" (this reader knows 1)',
    ],
    ["missing actions", JSON.stringify({ format: "chapgame", version: 1 }), "actions: must be an array"],
    ["negative g", base([], { g: -1 }), "g: must be a non-negative finite number"],
    ["bad gravity", base([], { gravity: [0] }), "gravity: must be an array of two finite numbers"],
    ["unknown top-level field", base([], { extra: 1 }), "extra: unknown field"],
    ["r = 0", base([disc("a", 0), disc("b", 5, { r: 0 })]), "actions[1].r: must be a positive finite number"],
    ["r < 0", base([disc("a", 0, { r: -1 })]), "actions[0].r: must be a positive finite number"],
    ["m = 0", base([disc("a", 0, { m: 0 })]), 'actions[0].m: must be a positive finite number or "Infinity"'],
    [
      "m < 0",
      base([disc("a", 0, { m: -2 })]),
      'actions[0].m: must be a positive finite number or "Infinity"',
    ],
    ["mu < 0", base([disc("a", 0, { mu: -0.1 })]), "actions[0].mu: must be a non-negative finite number"],
    [
      "missing x",
      base([{ time: 0, type: "addBody", id: "a", y: 0, r: 1, m: 1 }]),
      "actions[0].x: is required",
    ],
    ["NaN-like (string) x", base([disc("a", 0, { x: "1" })]), "actions[0].x: must be a finite number"],
    ["non-finite (null) y", base([disc("a", 0, { y: null })]), "actions[0].y: must be a finite number"],
    [
      "negative time",
      base([disc("a", 0, { time: -1 })]),
      "actions[0].time: must be a non-negative finite number",
    ],
    ["missing time", base([{ type: "removeBody", id: "a" }]), "actions[0].time: is required"],
    ["bad v", base([disc("a", 0, { v: [1, "x"] })]), "actions[0].v[1]: must be a finite number"],
    [
      "unknown type",
      base([{ time: 0, type: "explode", id: "a" }]),
      'actions[0].type: unknown action type "explode"',
    ],
    [
      "unknown field, with the known ones and the scene's spelling of a velocity",
      base([disc("a", 0, { vx: 1 })]),
      "actions[0].vx: unknown field (known: time, type, until, id, x, y, r, m, mu, v; a velocity is v: [vx, vy])",
    ],
    [
      "unknown line kind",
      base([{ time: 0, type: "addLine", id: "l", p1: [0, 0], p2: [1, 0], kind: "arc" }]),
      'actions[0].kind: must be one of "line", "ray", "segment"',
    ],
    [
      "degenerate line",
      base([{ time: 0, type: "addLine", id: "l", p1: [1, 1], p2: [1, 1], kind: "line" }]),
      "actions[0].p2: must differ from p1",
    ],
    ["empty id", base([disc("", 0)]), "actions[0].id: must be a non-empty string"],
    [
      "bad until",
      base([disc("a", 0, { until: { events: 1.5 } })]),
      "actions[0].until.events: must be a non-negative integer",
    ],
    [
      "duplicate body id",
      base([disc("a", 0), disc("a", 10)]),
      'actions[1].id: body "a" already exists at time 0',
    ],
    [
      "duplicate line id",
      base([
        { time: 0, type: "addLine", id: "l", p1: [0, 5], p2: [1, 5], kind: "line" },
        { time: 0, type: "addLine", id: "l", p1: [0, 9], p2: [1, 9], kind: "line" },
      ]),
      'actions[1].id: line "l" already exists at time 0',
    ],
    [
      "action on a missing body",
      base([disc("a", 0), { time: 1, type: "giveVelocity", id: "b", v: [1, 0] }]),
      'actions[1].id: no body "b" at time 1',
    ],
    [
      "action on a removed body",
      base([
        disc("a", 0),
        { time: 1, type: "removeBody", id: "a" },
        { time: 2, type: "updateBody", id: "a", r: 2 },
      ]),
      'actions[2].id: no body "a" at time 2',
    ],
    [
      "action before the body exists",
      base([disc("a", 0, { time: 3 }), { time: 1, type: "giveVelocity", id: "a", v: [1, 0] }]),
      'actions[1].id: no body "a" at time 1',
    ],
    [
      "missing line",
      base([{ time: 0, type: "removeLine", id: "l" }]),
      'actions[0].id: no line "l" at time 0',
    ],
    [
      "missing point",
      base([{ time: 0, type: "updatePoint", id: "p", p: [1, 1] }]),
      'actions[0].id: no point "p" at time 0',
    ],
    [
      "overlapping bodies",
      base([disc("a", 0), disc("b", 1.5)]),
      'actions[1]: body "b" would overlap body "a" at time 0',
    ],
    [
      "body grown into an overlap",
      base([disc("a", 0), disc("b", 3), { time: 0, type: "updateBody", id: "b", r: 2.5 }]),
      'actions[2]: body "b" would overlap body "a" at time 0',
    ],
    [
      "bodies placed into an overlap at a later time",
      base([disc("a", 0, { time: 2 }), disc("b", 1, { time: 2 })]),
      'actions[1]: body "b" would overlap body "a" at time 2',
    ],
    [
      "body onto a line",
      base([{ time: 0, type: "addLine", id: "w", p1: [0, -5], p2: [0, 5], kind: "segment" }, disc("a", 0.5)]),
      'actions[1]: body "a" would overlap line "w" at time 0',
    ],
    [
      "line onto a body",
      base([
        disc("a", 0),
        { time: 0, type: "addLine", id: "w", p1: [-5, 0.5], p2: [5, 0.5], kind: "segment" },
      ]),
      'actions[1]: line "w" would overlap body "a" at time 0',
    ],
    [
      "body onto a ray's end point",
      base([{ time: 0, type: "addLine", id: "w", p1: [0.5, 0], p2: [5, 0], kind: "ray" }, disc("a", 0)]),
      'actions[1]: body "a" would overlap line "w" at time 0',
    ],
    [
      "body onto a point at a later time (points do not move)",
      base([{ time: 0, type: "addPoint", id: "p", p: [0, 0] }, disc("a", 0.2, { time: 5 })]),
      'actions[1]: body "a" would overlap point "p" at time 5',
    ],
    [
      "friction with gravity",
      base([disc("a", 0, { mu: 0.1 })], { gravity: [0, -1] }),
      "actions[0].mu: friction (mu > 0) cannot be combined with a non-zero gravity field",
    ],
    [
      "gravity switched on with friction",
      base([disc("a", 0, { mu: 0.1 }), { time: 1, type: "setGlobal", gravity: [0, -1] }]),
      'actions[1].gravity: a non-zero gravity field cannot be combined with friction (body "a" has mu > 0: set its mu to 0 first)',
    ],
    [
      "gravity switched on with friction on several bodies: all of them named (one refusal each before)",
      base([
        disc("b", 0, { mu: 0.1 }),
        disc("a", 10, { mu: 0.2 }),
        disc("c", 20),
        { time: 1, type: "setGlobal", gravity: [0, -1] },
      ]),
      'actions[3].gravity: a non-zero gravity field cannot be combined with friction (bodies "a", "b" have mu > 0: set their mu to 0 first)',
    ],
  ];
  for (const [name, input, message] of cases)
    it(name, () => {
      const e = refused(input);
      expect(e.message.startsWith(message)).toBe(true);
      expect(e.message.startsWith(`${e.path}: `)).toBe(true);
    });
});

describe("parseScene names the value it refuses", () => {
  const cases: [string, Record<string, unknown>, string][] = [
    [
      "a number written as a string",
      { x: "1" },
      'actions[0].x: must be a finite number (got the string "1")',
    ],
    ["null", { r: null }, "actions[0].r: must be a positive finite number (got null)"],
    ["a boolean", { m: true }, 'actions[0].m: must be a positive finite number or "Infinity" (got true)'],
    ["an array", { y: [1, 2] }, "actions[0].y: must be a finite number (got an array of 2)"],
    ["an object", { mu: { a: 1 } }, "actions[0].mu: must be a non-negative finite number (got an object)"],
    ["an empty id", { id: "" }, 'actions[0].id: must be a non-empty string (got the string "")'],
    [
      "a long string, cut",
      { x: "x".repeat(100) },
      `actions[0].x: must be a finite number (got the string "${"x".repeat(40)}…")`,
    ],
    [
      "one component of a pair",
      { v: [0, "2"] },
      'actions[0].v[1]: must be a finite number (got the string "2")',
    ],
  ];
  for (const [name, patch, message] of cases)
    it(name, () => {
      expect(refused(base([disc("a", 0, patch)])).message).toBe(message);
    });
});

describe("parseScene names the value it refuses in the scene's frame too (audit of session 23: it did not)", () => {
  const scene = (fields: Record<string, unknown>) =>
    JSON.stringify({ format: "chapgame", version: 1, ...fields });
  const cases: [string, string, string][] = [
    [
      "another format",
      JSON.stringify({ format: "box2d", version: 1, actions: [] }),
      'format: must be "chapgame" (got the string "box2d")',
    ],
    ["no format", JSON.stringify({ version: 1, actions: [] }), 'format: must be "chapgame" (got undefined)'],
    ["an array for the scene", "[1]", "scene: must be a JSON object (got an array of 1)"],
    ["null for the scene", "null", "scene: must be a JSON object (got null)"],
    ["actions as an object", scene({ actions: { 0: {} } }), "actions: must be an array (got an object)"],
    ["no actions", scene({}), "actions: must be an array (got undefined)"],
    [
      "an action that is not an object",
      scene({ actions: [null] }),
      "actions[0]: must be an object (got null)",
    ],
    ["meta as an array", scene({ actions: [], meta: [1] }), "meta: must be an object (got an array of 1)"],
    [
      "an until that is not an object",
      scene({ actions: [disc("a", 0, { until: 5 })] }),
      "actions[0].until: must be an object with optional time and events (got 5)",
    ],
    [
      "an unknown action type, with the known ones",
      scene({ actions: [{ time: 0, type: "addDisc", id: "a" }] }),
      'actions[0].type: unknown action type "addDisc" (known: addBody, giveVelocity, updateBody, removeBody, addLine, updateLine, removeLine, addPoint, updatePoint, removePoint, setGlobal)',
    ],
  ];
  for (const [name, text, message] of cases)
    it(name, () => {
      expect(refused(text).message).toBe(message);
    });
});

describe("SceneError", () => {
  it("is a ChapgameError, so one catch covers every refused input (World, Timeline, parseScene)", () => {
    const e = refused(base([disc("a", 0, { r: -1 })]));
    expect(e).toBeInstanceOf(ChapgameError);
    expect(e.name).toBe("SceneError");
    expect([e.path, e.reason]).toEqual(["actions[0].r", "must be a positive finite number (got -1)"]);
    expect(e.message).toBe("actions[0].r: must be a positive finite number (got -1)");
  });

  it("has no leading colon when no field is at fault", () => {
    const e = new SceneError("", "the file is empty");
    expect(e).toBeInstanceOf(ChapgameError);
    expect(e.message).toBe("the file is empty");
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
