import { describe, expect, it } from "vitest";
import type { Action } from "../engineTypes";
import {
  actionIndexOf,
  actionName,
  capitalized,
  describeAction,
  explainRefusal,
  namedRefusal,
} from "./actionRefs";

const actions: Action[] = [
  { time: 0, type: "addBody", id: "b1", x: 0, y: 0, r: 1, m: 1 },
  { time: 2, type: "setGlobal", g: 0 },
  { time: 4.000000001, type: "updateBody", id: "b1", x: 5 },
];

describe("explainRefusal", () => {
  it("names actions[i] by its time, what it does and its object, the path in parentheses, the reason kept", () => {
    const message = 'actions[2].x: body "b1" would overlap body "c" at time 4 (once this action is in place)';
    expect(explainRefusal(message, "actions[2].x", actions)).toBe(
      'The action at t = 4 s that updates body "b1" (actions[2].x): body "b1" would overlap body "c" at time 4 (once this action is in place) (remove it from the Event log)',
    );
  });

  it("names an action without an id by what it does; a path that is the index alone works too", () => {
    expect(explainRefusal("actions[1]: bad", "actions[1]", actions)).toBe(
      "The action at t = 2 s that sets the globals (actions[1]): bad (remove it from the Event log)",
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

describe("actionName and namedRefusal", () => {
  it("name every action type as the author knows it", () => {
    const at = (type: string, id?: string) => actionName({ time: 1.5, type, id });
    expect(at("addBody", "b3")).toBe('the action at t = 1.5 s that adds disc "b3"');
    expect(at("giveVelocity", "a")).toBe('the action at t = 1.5 s that gives velocity to "a"');
    expect(at("updateBody", "a")).toBe('the action at t = 1.5 s that updates body "a"');
    expect(at("removeBody", "a")).toBe('the action at t = 1.5 s that removes body "a"');
    expect(at("addLine", "L")).toBe('the action at t = 1.5 s that adds line "L"');
    expect(at("updateLine", "L")).toBe('the action at t = 1.5 s that updates line "L"');
    expect(at("removeLine", "L")).toBe('the action at t = 1.5 s that removes line "L"');
    expect(at("addPoint", "P")).toBe('the action at t = 1.5 s that adds point "P"');
    expect(at("updatePoint", "P")).toBe('the action at t = 1.5 s that updates point "P"');
    expect(at("removePoint", "P")).toBe('the action at t = 1.5 s that removes point "P"');
    expect(at("setGlobal")).toBe("the action at t = 1.5 s that sets the globals");
  });

  it("say what a file's broken action holds, and nothing when it holds neither a time nor a known type", () => {
    expect(actionName({ time: 3, type: "setVelocity", id: "a" })).toBe("the action at t = 3 s");
    expect(actionName({ time: "soon", type: "addBody", id: "a" })).toBe('the action that adds disc "a"');
    expect(actionName({ time: 1, type: "addBody" })).toBe("the action at t = 1 s");
    expect(actionName({ type: "nope" })).toBeNull();
    expect(actionName(null)).toBeNull();
    expect(actionName(7)).toBeNull();
    expect(namedRefusal("actions[0].time: bad", "actions[0].time", [{ type: "nope" }])).toBe(
      "actions[0].time: bad",
    );
  });

  it("namedRefusal keeps the engine's reason after the name; a message not starting with its path is kept whole", () => {
    const list = [{ time: 1, type: "addBody", id: "b3" }];
    expect(namedRefusal('actions[0]: body "b3" would overlap', "actions[0]", list)).toBe(
      'the action at t = 1 s that adds disc "b3" (actions[0]): body "b3" would overlap',
    );
    expect(namedRefusal("something else", "actions[0]", list)).toBe(
      'the action at t = 1 s that adds disc "b3" (actions[0]): something else',
    );
    expect(namedRefusal("actions[4]: gone", "actions[4]", list)).toBe("actions[4]: gone");
    expect(namedRefusal("no path", null, list)).toBe("no path");
    expect(capitalized("the action")).toBe("The action");
  });
});
