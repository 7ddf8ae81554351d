// SceneView.lazy checks a group of actions as SceneView.of does (the same refusals, the same view
// after), reading the source's bodies only when an action needs them all.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { checkAndApply, SceneView, type ViewSource } from "./sceneRules.js";
import type { Action } from "./types.js";

/** Three discs and a line, at time 2. */
const STATE: ViewSource = {
  time: 2,
  g: 0,
  gravity: [0, 0],
  bodies: [
    { id: "a", x: 0, y: 0, r: 1, mu: 0 },
    { id: "b", x: 5, y: 0, r: 1, mu: 0 },
    { id: "c", x: 0, y: 5, r: 1, mu: 0 },
  ],
  lines: [{ id: "wall", p1: [-10, -10], p2: [10, -10], kind: "segment" }],
  points: [],
};

/** A lazy view of STATE that counts how often its bodies are read. The source is not told of the
 *  view's removals (the view must keep them itself). */
function lazyView() {
  const reads = { bodies: 0 };
  const view = SceneView.lazy({
    ...STATE,
    bodies: () => {
      reads.bodies++;
      return STATE.bodies;
    },
    hasBody: (id) => STATE.bodies.some((b) => b.id === id),
  });
  return { view, reads };
}

/** Each action's outcome ("ok" or the refusal), then the view's bodies. */
function outcome(view: SceneView, actions: readonly Action[]): unknown {
  const results = actions.map((a, i) => {
    try {
      checkAndApply(view, a, `actions[${i}]`);
      return "ok";
    } catch (e) {
      return (e as Error).message;
    }
  });
  return { results, bodies: [...view.bodies].sort(([p], [q]) => (p < q ? -1 : 1)) };
}

describe("SceneView.lazy", () => {
  it("answers velocities and removals without reading the bodies, and refuses what the eager view refuses", () => {
    const { view, reads } = lazyView();
    const group: Action[] = [
      { time: 2, type: "giveVelocity", id: "a", v: [1, 0] },
      { time: 2, type: "removeBody", id: "b" },
      { time: 2, type: "giveVelocity", id: "b", v: [1, 0] },
    ];
    checkAndApply(view, group[0] as Action, "actions[0]");
    checkAndApply(view, group[1] as Action, "actions[1]");
    expect(() => checkAndApply(view, group[2] as Action, "actions[2]")).toThrow(
      'actions[2].id: no body "b" at time 2',
    );
    expect(reads.bodies).toBe(0);
    // a body added where the removed one was: the bodies are read, without the removed one
    checkAndApply(view, { time: 2, type: "addBody", id: "d", x: 5, y: 0, r: 1, m: 1 }, "actions[3]");
    expect(reads.bodies).toBe(1);
    expect([...view.bodies.keys()].sort()).toEqual(["a", "c", "d"]);
  });

  it("gives the outcomes and the view SceneView.of gives, whatever the group", () => {
    const id = fc.constantFrom("a", "b", "c", "d");
    const at = fc.integer({ min: -2, max: 7 });
    const action: fc.Arbitrary<Action> = fc.oneof(
      id.map((i): Action => ({ time: 2, type: "giveVelocity", id: i, v: [1, 0] })),
      id.map((i): Action => ({ time: 2, type: "removeBody", id: i })),
      fc
        .tuple(id, at, at)
        .map(([i, x, y]): Action => ({ time: 2, type: "addBody", id: i, x, y, r: 1, m: 1 })),
      fc.tuple(id, at).map(([i, x]): Action => ({ time: 2, type: "updateBody", id: i, x })),
      fc.tuple(id, at).map(([i, x]): Action => ({ time: 2, type: "updateBody", id: i, mu: x > 3 ? 0.5 : 0 })),
      at.map((y): Action => ({ time: 2, type: "addPoint", id: "p", p: [0, y] })),
      at.map((y): Action => ({ time: 2, type: "setGlobal", gravity: [0, y > 5 ? -1 : 0] })),
    );
    fc.assert(
      fc.property(fc.array(action, { maxLength: 8 }), (group) => {
        expect(outcome(lazyView().view, group)).toEqual(outcome(SceneView.of(STATE), group));
      }),
      { seed: seedFor("SceneView.lazy against SceneView.of"), numRuns: 400 },
    );
  });
});
