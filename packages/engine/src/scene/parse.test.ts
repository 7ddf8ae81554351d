// parseScene: what it accepts and how it normalizes it (defaults, "Infinity", time order), and
// SceneError, the error it throws.
import { describe, expect, it } from "vitest";
import { ChapgameError } from "../sim/errors.js";
import { SceneError } from "./errors.js";
import { parseScene } from "./parse.js";
import { base, disc, refused } from "./testSupport.js";

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

describe("parseScene given bytes", () => {
  it("refuses a file read without an encoding (a Buffer, a Uint8Array, an ArrayBuffer), saying to decode it: it said `0: unknown field`", () => {
    const text = base([disc("a", 0)]);
    const bytes = new TextEncoder().encode(text);
    for (const input of [bytes, bytes.buffer, new DataView(bytes.buffer)]) {
      const e = refused(input);
      expect(e.path).toBe("scene");
      expect(e.reason).toMatch(
        new RegExp(
          `^must be the scene's JSON text or its object, not bytes \\(got an? \\w+ of ${bytes.length} bytes\\): decode them as UTF-8 first`,
        ),
      );
    }
    expect(parseScene(new TextDecoder().decode(bytes)).actions).toHaveLength(1);
  });
});
