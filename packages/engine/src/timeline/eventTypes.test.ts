/**
 * Log entries and World events narrow on their kind in TypeScript (audit of session 20: every
 * collision handler needed `!` or a cast). The type assertions are checked by the typecheck (tsc
 * over the tests); the runtime assertions check that the values agree with the types.
 */
import { describe, expect, expectTypeOf, it } from "vitest";
import type { ActionType, Vec2 } from "../scene/types.js";
import type { WorldEvent } from "../sim/types.js";
import { World } from "../sim/world.js";
import { Timeline } from "./timeline.js";
import type { LogEvent } from "./types.js";

describe("event types narrow on their kind", () => {
  it("a LogEvent: collisions have two ids, a point and a normal; stops one id and a point; actions their type", () => {
    const tl = new Timeline({ g: 1 });
    tl.apply({ time: 0, type: "addLine", id: "w", p1: [10, -5], p2: [10, 5], kind: "line" });
    tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [4, 0] });
    tl.apply({ time: 0, type: "addBody", id: "b", x: 4, y: 0, r: 1, m: 1, mu: 0.5 });
    tl.prolong({});
    const seen = new Set<string>();
    for (const e of tl.eventRange(0, tl.eventCount) as LogEvent[]) {
      seen.add(e.type);
      if (e.type === "action") {
        expectTypeOf(e.action).toEqualTypeOf<ActionType>();
        expectTypeOf(e.point).toEqualTypeOf<null>();
        expect(e.ids).toHaveLength(1);
      } else if (e.type === "stop") {
        expectTypeOf(e.ids).toEqualTypeOf<[string]>();
        expectTypeOf(e.point).toEqualTypeOf<Vec2>();
        expect(e.normal).toBeNull();
        expect(e.impulse).toBe(0);
      } else {
        expectTypeOf(e.ids).toEqualTypeOf<[string, string]>();
        expectTypeOf(e.normal).toEqualTypeOf<Vec2>();
        expectTypeOf(e.impulse).toEqualTypeOf<number>();
        expect(e.ids).toHaveLength(2);
        expect(e.point).not.toBeNull();
        expect(e.normal).not.toBeNull();
      }
      // read without narrowing, as before
      expect(e.ids.includes("a") || e.ids.includes("b") || e.type === "action").toBe(true);
    }
    expect([...seen].sort()).toEqual(["action", "bodyBody", "bodyLine", "stop"]);
  });

  it("a WorldEvent: b is a string for a collision and null for a stop", () => {
    const w = new World({ g: 1 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 4 });
    w.addBody("b", { x: 4, y: 0, r: 1, m: 1, mu: 0.5 });
    const kinds: string[] = [];
    w.advance({}, (e: WorldEvent) => {
      kinds.push(e.kind);
      if (e.kind === "stop") {
        expectTypeOf(e.b).toEqualTypeOf<null>();
        expect(e.b).toBeNull();
      } else {
        expectTypeOf(e.b).toEqualTypeOf<string>();
        expect(typeof e.b).toBe("string");
      }
    });
    expect(kinds).toEqual(["bodyBody", "stop"]);
  });
});
