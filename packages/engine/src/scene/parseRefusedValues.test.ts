// parseScene names the value it refuses, "(got …)", in actions and in the scene's frame alike.
import { describe, expect, it } from "vitest";
import { base, disc, refused } from "./testSupport.js";

describe("parseScene names the value it refuses", () => {
  const cases: [string, Record<string, unknown>, string][] = [
    [
      "a number written as a string",
      { x: "1" },
      'actions[0].x: must be a finite number (got the string "1")',
    ],
    ["null", { r: null }, "actions[0].r: must be a positive finite number (got null)"],
    ["a boolean", { m: true }, 'actions[0].m: must be a positive finite number or "Infinity" (got true)'],
    [
      // review of session 29: a Timeline's toScene() saved with JSON.stringify, not serializeScene
      "a mass of null, what JSON.stringify writes for Infinity",
      { m: null },
      'actions[0].m: must be a positive finite number or "Infinity" (got null): JSON.stringify writes Infinity as null; serializeScene writes "Infinity"',
    ],
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
    // a version that is not a number is told to be one, whatever it is (the number 1 or a newer one)
    [
      "a version written as a string",
      JSON.stringify({ format: "chapgame", version: "1", actions: [] }),
      'version: must be the number 1 (got the string "1")',
    ],
    [
      "a newer version written as a string",
      JSON.stringify({ format: "chapgame", version: "2", actions: [] }),
      'version: must be the number 1 (got the string "2")',
    ],
    [
      "no version",
      JSON.stringify({ format: "chapgame", actions: [] }),
      "version: must be the number 1 (got undefined)",
    ],
    ["a null version", scene({ version: null, actions: [] }), "version: must be the number 1 (got null)"],
    // a number other than 1: unsupported, and from a newer chapgame only when it is a later whole number
    [
      "a fractional version",
      scene({ version: 1.5, actions: [] }),
      "version: unsupported version 1.5 (this reader knows 1)",
    ],
    ["version 0", scene({ version: 0, actions: [] }), "version: unsupported version 0 (this reader knows 1)"],
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

describe("parseScene names a version given as an object's number as it is", () => {
  it("NaN and Infinity (NaN was written as JSON writes it: null)", () => {
    const frame = (version: number) => ({ format: "chapgame", version, actions: [] });
    expect(refused(frame(Number.NaN)).message).toBe("version: unsupported version NaN (this reader knows 1)");
    expect(refused(frame(Infinity)).message).toBe(
      "version: unsupported version Infinity (this reader knows 1)",
    );
  });
});
