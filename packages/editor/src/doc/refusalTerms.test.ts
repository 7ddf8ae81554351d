import { describe, expect, it } from "vitest";
import type { Action } from "../engineTypes";
import { refusalInUserTerms } from "./refusalTerms";

const update: Action = { time: 0, type: "updateBody", id: "A", r: -5 };
const addDisc: Action = { time: 0, type: "addBody", id: "b1", x: 0, y: 0, r: 1, m: 1 };

describe("refusalInUserTerms", () => {
  it("names a body's field as its cell: A r, A vx, A vy", () => {
    expect(refusalInUserTerms("action.r: must be a positive finite number", "action.r", update)).toBe(
      "A r: must be a positive finite number",
    );
    expect(refusalInUserTerms("action.v[0]: must be finite", "action.v[0]", update)).toBe(
      "A vx: must be finite",
    );
    const strike: Action = { time: 0, type: "giveVelocity", id: "A", v: [0, Number.POSITIVE_INFINITY] };
    expect(refusalInUserTerms("action.v[1]: must be finite", "action.v[1]", strike)).toBe(
      "A vy: must be finite",
    );
    // the column is headed μ (audit of session 20: "A mu" beside "A μ: must be a number")
    expect(refusalInUserTerms("action.mu: must be a non-negative finite number", "action.mu", update)).toBe(
      "A μ: must be a non-negative finite number",
    );
  });

  it("a vector refused whole with one component not finite names that component's cell", () => {
    const v: Action = { time: 0, type: "updateBody", id: "A", v: [3, Number.POSITIVE_INFINITY] };
    const whole = "must be an array of two finite numbers";
    expect(refusalInUserTerms(`action.v: ${whole}`, "action.v", v)).toBe("A vy: must be a finite number");
    const both: Action = { time: 0, type: "updateBody", id: "A", v: [Number.NaN, Number.NaN] };
    expect(refusalInUserTerms(`action.v: ${whole}`, "action.v", both)).toBe(`A v: ${whole}`);
    const gravity: Action = { time: 0, type: "setGlobal", gravity: [Number.NaN, 0] };
    expect(refusalInUserTerms(`action.gravity: ${whole}`, "action.gravity", gravity)).toBe(
      "gravity x: must be a finite number",
    );
  });

  it("names globals, line ends and point coordinates as their cells", () => {
    const global: Action = { time: 0, type: "setGlobal", g: -1 };
    expect(refusalInUserTerms("action.g: must be positive", "action.g", global)).toBe("g: must be positive");
    expect(refusalInUserTerms("action.gravity[1]: must be finite", "action.gravity[1]", global)).toBe(
      "gravity y: must be finite",
    );
    const line: Action = { time: 0, type: "updateLine", id: "L", p1: [0, 0] };
    expect(refusalInUserTerms("action.p1[0]: must be finite", "action.p1[0]", line)).toBe(
      "L x1: must be finite",
    );
    const point: Action = { time: 0, type: "updatePoint", id: "P", p: [0, 0] };
    expect(refusalInUserTerms("action.p[1]: must be finite", "action.p[1]", point)).toBe(
      "P y: must be finite",
    );
  });

  it("a line end meeting the other end names both ends by their cells", () => {
    // (it said "L p1: must differ from p1 and p2 of the line": fields the Lines table does not have)
    const moved: Action = { time: 0, type: "updateLine", id: "L", p1: [128, 28] };
    expect(refusalInUserTerms("action.p1: must differ from p1 and p2 of the line", "action.p1", moved)).toBe(
      "L x1, y1: must differ from x2, y2 (a line needs two different ends)",
    );
    const both: Action = { time: 0, type: "updateLine", id: "L", p1: [0, 0], p2: [1e-31, 0] };
    expect(
      refusalInUserTerms(
        "action.p2: must be at least 1e-30 from p1 and p2 of the line in x or y (got 1e-31): a shorter direction underflows the contact tests",
        "action.p2",
        both,
      ),
    ).toBe(
      "L x2, y2: must be at least 1e-30 from x1, y1 in x or y (got 1e-31): a shorter direction underflows the contact tests",
    );
    const added: Action = { time: 0, type: "addLine", id: "l1", p1: [1, 1], p2: [1, 1], kind: "ray" };
    expect(refusalInUserTerms("action.p2: must differ from p1 (got [1, 1])", "action.p2", added)).toBe(
      "new line x2, y2: must differ from x1, y1 (got 1, 1): a line needs two different ends",
    );
    const onto: Action = { time: 0, type: "updateLine", id: "L", p1: [4, -2.5] };
    expect(refusalInUserTerms("action.p1: must differ from p2 (got [4, -2.5])", "action.p1", onto)).toBe(
      "L x1, y1: must differ from x2, y2 (got 4, -2.5): a line needs two different ends",
    );
  });

  it("a refused action as a whole keeps the engine's reason; an added disc is 'a new disc here'", () => {
    const overlap = 'body "A" would overlap body "B" at time 0';
    expect(refusalInUserTerms(`action: ${overlap}`, "action", update)).toBe(overlap);
    expect(refusalInUserTerms('action: body "b1" would overlap body "B" at time 2', "action", addDisc)).toBe(
      'a new disc here would overlap body "B" at time 2',
    );
    const addLine: Action = { time: 0, type: "addLine", id: "l1", p1: [0, 0], p2: [1, 0], kind: "segment" };
    expect(refusalInUserTerms('action: line "l1" would overlap body "A" at time 0', "action", addLine)).toBe(
      'a new line here would overlap body "A" at time 0',
    );
  });

  it("a field of an added object says it is the new one's", () => {
    expect(refusalInUserTerms("action.r: must be a positive finite number", "action.r", addDisc)).toBe(
      "new disc r: must be a positive finite number",
    );
  });

  it("leaves other actions' paths and messages without a path alone", () => {
    const later = 'actions[3]: body "b" would overlap body "a" at time 4';
    expect(refusalInUserTerms(later, "actions[3]", update)).toBe(later);
    expect(refusalInUserTerms("engine restarted", null, update)).toBe("engine restarted");
  });
});
