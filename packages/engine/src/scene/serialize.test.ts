import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { FIELD_MIN, SPEED_MIN } from "../tolerances.js";
import { SceneError } from "./errors.js";
import { parseScene } from "./parse.js";
import { presets } from "./presets.js";
import { serializeScene } from "./serialize.js";
import type { Action, SceneFile } from "./types.js";

describe("serializeScene", () => {
  it('writes a stable key order, one action per line, infinite mass as "Infinity"', () => {
    const s: SceneFile = {
      format: "chapgame",
      version: 1,
      g: 1,
      gravity: [0, 0],
      actions: [
        { v: [1, 2], mu: 0, m: Infinity, r: 1, y: 0, x: 0, id: "a", type: "addBody", time: 0 } as Action,
        { time: 1, type: "giveVelocity", id: "a", v: [0, 0], until: { events: 3, time: 2 } },
      ],
    };
    expect(serializeScene(s)).toBe(
      [
        "{",
        '  "format": "chapgame",',
        '  "version": 1,',
        '  "g": 1,',
        '  "gravity": [0, 0],',
        '  "actions": [',
        '    { "time": 0, "type": "addBody", "id": "a", "x": 0, "y": 0, "r": 1, "m": "Infinity", "mu": 0, "v": [1, 2] },',
        '    { "time": 1, "type": "giveVelocity", "id": "a", "v": [0, 0], "until": { "time": 2, "events": 3 } }',
        "  ]",
        "}",
        "",
      ].join("\n"),
    );
  });
  it("round-trips every preset exactly", () => {
    for (const p of presets) {
      const s = p.make();
      const back = parseScene(serializeScene(s));
      expect(back, p.id).toEqual(parseScene(s));
      expect(serializeScene(back)).toBe(serializeScene(s));
    }
  });
  it("keeps the sign of -0 (regression: found by the round-trip property)", () => {
    const s = parseScene({
      format: "chapgame",
      version: 1,
      actions: [{ time: 0, type: "addPoint", id: "p", p: [-0, 0] }],
    });
    const back = parseScene(serializeScene(s)).actions[0];
    expect(back?.type === "addPoint" && Object.is(back.p[0], -0)).toBe(true);
  });
  it("takes a file that leaves g and gravity out, as a scene file may, and leaves them out (it required g)", () => {
    const file = JSON.parse(
      '{"format": "chapgame", "version": 1, "actions": [{"time": 0, "type": "addBody", "id": "a", "x": 0, "y": 0, "r": 1, "m": "Infinity"}]}',
    );
    const text = serializeScene(file);
    expect(text).toBe(
      [
        "{",
        '  "format": "chapgame",',
        '  "version": 1,',
        '  "actions": [',
        '    { "time": 0, "type": "addBody", "id": "a", "x": 0, "y": 0, "r": 1, "m": "Infinity" }',
        "  ]",
        "}",
        "",
      ].join("\n"),
    );
    expect(parseScene(text)).toEqual(parseScene(file)); // g 9.81 and gravity [0, 0] read back
    // one of them given: that one is written
    expect(serializeScene({ ...file, gravity: [0, -1] })).toContain('"version": 1,\n  "gravity": [0, -1],\n');
    expect(serializeScene({ ...file, g: 0 })).toContain('"version": 1,\n  "g": 0,\n  "actions"');
    // still checked as parseScene checks them when given
    expect(() => serializeScene({ ...file, g: -1 })).toThrow(
      "g: must be a non-negative finite number (got -1)",
    );
  });
  it("keeps meta", () => {
    const s = parseScene({ format: "chapgame", version: 1, actions: [], meta: { view: [1, 2] } });
    expect(parseScene(serializeScene(s)).meta).toEqual({ view: [1, 2] });
  });
});

describe("serializeScene round trip (property)", () => {
  it("parse(serialize(s)) equals s for random valid scenes of spread-out bodies and lines", () => {
    const seed = seedFor("serialize round-trip property");
    const num = fc.double({ noNaN: true, noDefaultInfinity: true, min: -1e6, max: 1e6 });
    const pos = fc.double({ noNaN: true, noDefaultInfinity: true, min: 1e-3, max: 1 });
    // valid scenes only: speeds and fields are 0 or at least SPEED_MIN / FIELD_MIN in size
    const speed = num.filter((v) => v === 0 || Math.abs(v) >= SPEED_MIN);
    const bodies = fc.array(fc.tuple(num, pos, fc.oneof(pos, fc.constant(Infinity)), speed, speed), {
      maxLength: 8,
    });
    const time = fc.double({ min: 0, max: 100, noNaN: true }).filter((t) => t === 0 || t >= FIELD_MIN);
    fc.assert(
      fc.property(bodies, time, (bs, t) => {
        const actions: Action[] = bs.map(([x, r, m, vx, vy], i) => ({
          time: 0,
          type: "addBody",
          id: `b${i}`,
          x: i * 10,
          y: x,
          r,
          m,
          mu: 0,
          v: [vx, vy],
        }));
        if (bs.length > 0) actions.push({ time: t, type: "updateBody", id: "b0", v: [t, -t], until: {} });
        actions.push({ time: t, type: "addLine", id: "l", p1: [-1, 2e6], p2: [1, 2e6], kind: "ray" });
        const s: SceneFile = { format: "chapgame", version: 1, g: t, gravity: [0, 0], actions };
        expect(parseScene(serializeScene(s))).toEqual(s);
      }),
      { seed, verbose: true },
    );
  });

  it("refuses to write what parseScene would refuse field by field, naming the field (it wrote unloadable files)", () => {
    const scene = (actions: unknown[], extra: Record<string, unknown> = {}) =>
      ({ format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions, ...extra }) as unknown as SceneFile;
    const add = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
    const cases: [SceneFile, string][] = [
      [scene([{ ...add, x: Number.NaN }]), "actions[0].x: must be a finite number"],
      [scene([add, { ...add, id: "b", r: -1 }]), "actions[1].r: must be a positive finite number"],
      [scene([{ time: 0, type: "addBody", id: "a", y: 0, r: 1, m: 1 }]), "actions[0].x: is required"],
      [scene([{ time: 0, type: "explode", id: "a" }]), 'actions[0].type: unknown action type "explode"'],
      [scene([{ ...add, label: "cue" }]), "actions[0].label: unknown field"],
      [scene([], { g: Number.NaN }), "g: must be a non-negative finite number"],
      [scene([], { gravity: [0] }), "gravity: must be an array of two finite numbers"],
      [scene([], { meta: [1] }), "meta: must be an object"],
      [{ format: "chapgame", version: 1 } as unknown as SceneFile, "actions: must be an array"],
      // regression (acceptance audit): these were written as version-1 files without complaint
      [{} as unknown as SceneFile, 'format: must be "chapgame"'],
      [scene([], { version: 2 }), "version: unsupported version 2"],
      [scene([], { foo: 1 }), "foo: unknown field"],
      [scene([], { format: undefined }), 'format: must be "chapgame"'],
    ];
    for (const [s, message] of cases) {
      expect(() => serializeScene(s)).toThrow(SceneError);
      expect(() => serializeScene(s)).toThrow(message);
    }
  });

  it("writes a valid action as given (defaults not filled in)", () => {
    const s = {
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, 0],
      actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }],
    } as SceneFile;
    expect(serializeScene(s)).toContain(
      '{ "time": 0, "type": "addBody", "id": "a", "x": 0, "y": 0, "r": 1, "m": 1 }',
    );
  });
});
