import { describe, expect, it } from "vitest";
import type { Action } from "../engineTypes";
import { actionIndexOf, describeAction, explainRefusal } from "./actionRefs";

const actions: Action[] = [
  { time: 0, type: "addBody", id: "b1", x: 0, y: 0, r: 1, m: 1 },
  { time: 2, type: "setGlobal", g: 0 },
  { time: 4.000000001, type: "updateBody", id: "b1", x: 5 },
];

describe("explainRefusal", () => {
  it("appends which action actions[i] is, keeping the engine's message at the start", () => {
    const message = 'actions[2].x: body "b1" would overlap body "c" at time 4 (once this action is in place)';
    expect(explainRefusal(message, "actions[2].x", actions)).toBe(
      `${message} — actions[2] is the action at t = 4 s: update body "b1" (remove it from the Event log)`,
    );
  });

  it("names an action without an id by its type; a path that is the index alone works too", () => {
    expect(explainRefusal("actions[1]: bad", "actions[1]", actions)).toBe(
      "actions[1]: bad — actions[1] is the action at t = 2 s: set global (remove it from the Event log)",
    );
  });

  it("leaves other messages alone: no path, another path, an index the list does not hold", () => {
    expect(explainRefusal("action.x: bad", "action.x", actions)).toBe("action.x: bad");
    expect(explainRefusal("engine restarted", null, actions)).toBe("engine restarted");
    expect(explainRefusal("actions[3].id: no body", "actions[3].id", actions)).toBe("actions[3].id: no body");
  });

  it("reads the index of a path and names an action", () => {
    expect(actionIndexOf("actions[11].id")).toBe(11);
    expect(actionIndexOf("myactions[1]")).toBeNull();
    expect(describeAction({ time: 1, type: "removePoint", id: 'p"q' })).toBe('remove point "p\\"q"');
  });
});
