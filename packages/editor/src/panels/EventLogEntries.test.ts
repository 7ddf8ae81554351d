// What an Event log entry says (its kind in words), lights (every participant with its kind) and
// selects (the object of an action by the action's type, a collision's body): pure functions of
// EventLog.tsx.
import { describe, expect, it } from "vitest";
import type { LogEvent } from "../engineTypes";
import { highlightOf, kindLabel, selectionOf } from "./EventLog";

describe("Event log entries", () => {
  it("labels an entry by its kind, with the action's type in words for an action", () => {
    const base = { time: 1, ids: ["a"], point: null, normal: null, impulse: null };
    const hit = { time: 1, point: [0, 0] as const, normal: [1, 0] as const, impulse: 1 };
    expect(kindLabel({ ...hit, ids: ["a", "w"], type: "bodyLine" })).toBe("body–line");
    expect(kindLabel({ ...base, type: "action", action: "setGlobal" })).toBe("action: set global");
    expect(kindLabel({ ...base, type: "action", action: "removePoint" })).toBe("action: remove point");
  });

  it("highlightOf: every participant with its kind; an action's object; nothing for setGlobal", () => {
    const base = { time: 1, point: null, normal: null, impulse: null };
    const hit = { time: 1, point: [0, 0] as const, normal: [1, 0] as const, impulse: 1 };
    const stop = { time: 1, point: [0, 0] as const, normal: null, impulse: 0 };
    expect(highlightOf({ ...hit, type: "bodyBody", ids: ["a", "b"] })).toEqual(["body:a", "body:b"]);
    expect(highlightOf({ ...hit, type: "bodyPoint", ids: ["a", "p"] })).toEqual(["body:a", "point:p"]);
    expect(highlightOf({ ...stop, type: "stop", ids: ["a"] })).toEqual(["body:a"]);
    expect(highlightOf({ ...base, type: "action", action: "removePoint", ids: ["p"] })).toEqual(["point:p"]);
    expect(highlightOf({ ...base, type: "action", action: "setGlobal", ids: [] })).toEqual([]);
  });

  it("selectionOf: an action's object by the action's type, a collision's body, nothing for setGlobal", () => {
    const base = { time: 1, point: null, normal: null, impulse: null };
    const action = (action: NonNullable<LogEvent["action"]>, ids = ["x"]) =>
      selectionOf({ ...base, type: "action", action, ids });
    expect(action("updateLine")).toEqual({ kind: "line", id: "x" });
    expect(action("removeLine")).toEqual({ kind: "line", id: "x" });
    expect(action("updatePoint")).toEqual({ kind: "point", id: "x" });
    expect(action("removePoint")).toEqual({ kind: "point", id: "x" });
    expect(action("giveVelocity")).toEqual({ kind: "body", id: "x" });
    expect(action("removeBody")).toEqual({ kind: "body", id: "x" });
    expect(action("setGlobal", [])).toBeNull();
    const hit = { time: 1, point: [0, 0] as const, normal: [1, 0] as const, impulse: 1 };
    const stop = { time: 1, point: [0, 0] as const, normal: null, impulse: 0 };
    expect(selectionOf({ ...hit, type: "bodyPoint", ids: ["a", "p"] })).toEqual({ kind: "body", id: "a" });
    expect(selectionOf({ ...stop, type: "stop", ids: ["a"] })).toEqual({ kind: "body", id: "a" });
  });
});
