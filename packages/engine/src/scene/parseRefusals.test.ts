// parseScene refuses invalid scenes naming the path and the reason: the scene's frame, every kind
// of field, and the scene rules (ids that exist, duplicates, overlaps, friction under gravity).
import { describe, expect, it } from "vitest";
import { base, disc, refused } from "./testSupport.js";

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
      'a version written as a string: it must be the number 1 (it said unsupported version "1" (this reader knows 1))',
      JSON.stringify({ format: "chapgame", version: "1", actions: [] }),
      'version: must be the number 1 (got the string "1")',
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
      "actions[0].p2: must differ from p1 (got [1, 1])",
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
      "body onto two lines, the later-added with the smaller id: the smallest id is named, as the World does",
      base([
        { time: 0, type: "addLine", id: "w2", p1: [0, -5], p2: [0, 5], kind: "segment" },
        { time: 0, type: "addLine", id: "w1", p1: [0.4, -5], p2: [0.4, 5], kind: "segment" },
        disc("a", 0.2),
      ]),
      'actions[2]: body "a" would overlap line "w1" at time 0',
    ],
    [
      "body onto two points, the later-added with the smaller id",
      base([
        { time: 0, type: "addPoint", id: "q", p: [0, 0] },
        { time: 0, type: "addPoint", id: "p", p: [0.3, 0] },
        disc("a", 0.1),
      ]),
      'actions[2]: body "a" would overlap point "p" at time 0',
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
      "actions[0].mu: friction (mu > 0) cannot be combined with a non-zero gravity field (got 0.1): set mu to 0, or the gravity field to [0, 0] first",
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
