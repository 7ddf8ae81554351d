import { describe, expect, it } from "vitest";
import { sceneOf } from "../testing/scenes";
import { withoutAction } from "./removeAction";

const scene = sceneOf([
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
  { time: 1, type: "giveVelocity", id: "a", v: [1, 0] },
  { time: 1, type: "setGlobal", g: 0 },
]);

describe("withoutAction", () => {
  it("removes exactly the action at the index, the rest kept in order", () => {
    const out = withoutAction(scene, 1, { time: 1, type: "giveVelocity", id: "a" });
    expect(out.actions).toEqual([scene.actions[0], scene.actions[2]]);
    expect(scene.actions).toHaveLength(3);
    expect(withoutAction(scene, 2, { time: 1, type: "setGlobal", id: null }).actions).toHaveLength(2);
  });

  it("refuses when the index no longer holds that action (time, type or id differ, or no action)", () => {
    const stale = 'The scene changed since the Event log listed give velocity to "a" at t = 1 s';
    expect(() => withoutAction(scene, 2, { time: 1, type: "giveVelocity", id: "a" })).toThrow(stale);
    expect(() => withoutAction(scene, 3, { time: 1, type: "giveVelocity", id: "a" })).toThrow(stale);
    expect(() => withoutAction(scene, 1, { time: 1, type: "giveVelocity", id: "b" })).toThrow(
      "nothing was removed",
    );
    expect(() => withoutAction(scene, 1, { time: 2, type: "giveVelocity", id: "a" })).toThrow(
      "nothing was removed",
    );
  });

  it("says an action already removed is no longer in the scene (a second click said 'try again')", () => {
    const once = withoutAction(scene, 1, { time: 1, type: "giveVelocity", id: "a" });
    expect(() => withoutAction(once, 1, { time: 1, type: "giveVelocity", id: "a" })).toThrow(
      'give velocity to "a" at t = 1 s is no longer in the scene: nothing was removed.',
    );
  });
});
