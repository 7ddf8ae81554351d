import { describe, expect, it } from "vitest";
import { ACTION_FIELDS, ACTION_TYPES, checkAction } from "./action.js";

describe("checkAction", () => {
  it("returns the keys in canonical order whichever optional fields are given (mu came after v)", () => {
    const canonical = ["time", "type", ...ACTION_FIELDS.addBody.map((f) => f[0]), "until"];
    const inputs = [
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0.2 },
      { v: [1, 0], until: { time: 1 }, mu: 0.1, m: 1, r: 1, y: 0, x: 0, id: "a", type: "addBody", time: 0 },
    ];
    for (const raw of inputs) {
      const keys = Object.keys(checkAction(raw, "a"));
      expect(keys).toEqual(canonical.filter((k) => keys.includes(k)));
      expect(keys).toContain("mu");
      expect(keys).toContain("v");
    }
  });
});

describe("checkAction's path", () => {
  it('defaults to "action" (a call without it named the field "undefined.r")', () => {
    // Review of session 29: checkAction(raw) from JavaScript said "undefined.r: must be …".
    const raw = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: -1, m: 1 };
    expect(() => checkAction(raw)).toThrow(/^action\.r: must be a positive finite number \(got -1\)$/);
    expect(() => checkAction(raw, "actions[4]")).toThrow(/^actions\[4\]\.r: /);
    expect(() => checkAction(null)).toThrow(/^action: must be an object \(got null\)$/);
  });
});

describe("checkAction defaults", () => {
  it("gives each addBody its own default velocity array (it was one shared array for all)", () => {
    const raw = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
    const a = checkAction(raw, "a") as unknown as { v: number[] };
    const b = checkAction(raw, "b") as unknown as { v: number[] };
    expect(a.v).not.toBe(b.v);
    a.v[0] = 5;
    expect(b.v).toEqual([0, 0]);
    expect(checkAction(raw, "c")).toMatchObject({ v: [0, 0] });
  });
});

describe("ACTION_TYPES", () => {
  it("lists the eleven types in the format's order, and cannot be changed at run time", () => {
    expect(ACTION_TYPES).toEqual(Object.keys(ACTION_FIELDS));
    expect(ACTION_TYPES[0]).toBe("addBody");
    expect(ACTION_TYPES.at(-1)).toBe("setGlobal");
    expect(Object.isFrozen(ACTION_TYPES)).toBe(true);
    const mutable = ACTION_TYPES as unknown as string[];
    expect(() => mutable.push("addDisc")).toThrow(TypeError);
    expect(() => mutable.sort()).toThrow(TypeError);
    expect(ACTION_TYPES).toHaveLength(11);
    // The refusal of an unknown type still quotes the list as it was.
    expect(() => checkAction({ time: 0, type: "addDisc", id: "a" }, "a")).toThrow(
      `a.type: unknown action type "addDisc" (known: ${Object.keys(ACTION_FIELDS).join(", ")})`,
    );
  });
});
