// SceneView.lazy checks a group of actions as SceneView.of does (the same refusals, the same view
// after), reading the source's bodies only when an action needs them all.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { World } from "../sim/world.js";
import { applyToWorld } from "../timeline/applyAction.js";
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

/** A World holding `state` (all at rest). */
function worldOf(state: ViewSource): World {
  const w = new World({ g: state.g, gravity: state.gravity, time: state.time });
  for (const b of state.bodies) w.addBody(b.id, { x: b.x, y: b.y, r: b.r, m: 1, mu: b.mu });
  for (const l of state.lines) w.addLine(l.id, l.p1, l.p2, l.kind);
  for (const p of state.points) w.addPoint(p.id, p.p);
  return w;
}

/** A lazy view of a World (as a Timeline makes it: actionGroup.ts), counting how often the World's
 *  bodies are all read. */
function lazyViewOf(w: World) {
  const reads = { bodies: 0 };
  const view = SceneView.lazy({
    time: w.time,
    g: w.g,
    gravity: w.gravity,
    lines: w.lines(),
    points: w.points(),
    bodies: () => {
      reads.bodies++;
      return w.bodies();
    },
    hasBody: (id) => w.hasBody(id),
    body: (id) => w.body(id),
    forEachBodyNear: (x, y, r, visit) => w.forEachBodyNear(x, y, r, visit),
    forEachBodyNearSegment: (x1, y1, x2, y2, visit) => w.forEachBodyNearSegment(x1, y1, x2, y2, visit),
  });
  return { view, reads };
}

/**
 * Each action's outcome ("ok" or the refusal) when checked against a view of a World holding
 * `state` (lazy, or SceneView.of) and then applied to the World, as a Timeline does (up to the
 * first refusal of the World itself); then the view's bodies.
 */
function outcome(state: ViewSource, lazy: boolean, actions: readonly Action[]): unknown {
  const w = worldOf(state);
  const view = lazy ? lazyViewOf(w).view : SceneView.of(state);
  const results: string[] = [];
  for (const [i, a] of actions.entries()) {
    try {
      checkAndApply(view, a, `actions[${i}]`);
    } catch (e) {
      results.push((e as Error).message);
      continue;
    }
    try {
      applyToWorld(w, a, `actions[${i}]`);
      results.push("ok");
    } catch (e) {
      results.push(`world: ${(e as Error).message}`);
      break;
    }
  }
  return { results, bodies: [...view.bodies].sort(([p], [q]) => (p < q ? -1 : 1)) };
}

describe("SceneView.lazy", () => {
  it("answers velocities, removals, additions and moves without reading the bodies; an infinite line reads them", () => {
    const w = worldOf(STATE);
    const { view, reads } = lazyViewOf(w);
    const check = (a: Action, i: number) => {
      checkAndApply(view, a, `actions[${i}]`);
      applyToWorld(w, a, `actions[${i}]`);
    };
    check({ time: 2, type: "giveVelocity", id: "a", v: [1, 0] }, 0);
    check({ time: 2, type: "removeBody", id: "b" }, 1);
    expect(() => check({ time: 2, type: "giveVelocity", id: "b", v: [1, 0] }, 2)).toThrow(
      'actions[2].id: no body "b" at time 2',
    );
    // a body added where the removed one was, then one onto it, then a move onto "c"
    check({ time: 2, type: "addBody", id: "d", x: 5, y: 0, r: 1, m: 1 }, 3);
    expect(() => check({ time: 2, type: "addBody", id: "e", x: 5.5, y: 0, r: 1, m: 1 }, 4)).toThrow(
      'actions[4]: body "e" would overlap body "d" at time 2',
    );
    expect(() => check({ time: 2, type: "addBody", id: "d", x: 9, y: 0, r: 1, m: 1 }, 5)).toThrow(
      'actions[5].id: body "d" already exists at time 2',
    );
    expect(() => check({ time: 2, type: "updateBody", id: "d", x: 0, y: 4.5 }, 6)).toThrow(
      'actions[6]: body "d" would overlap body "c" at time 2',
    );
    expect(() => check({ time: 2, type: "addPoint", id: "p", p: [5, 0.5] }, 7)).toThrow(
      'actions[7]: point "p" would overlap body "d" at time 2',
    );
    expect(reads.bodies).toBe(0);
    expect(() =>
      check({ time: 2, type: "addLine", id: "l", p1: [0, 0.5], p2: [1, 0.5], kind: "line" }, 8),
    ).toThrow('actions[8]: line "l" would overlap body "a" at time 2');
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
        expect(outcome(STATE, true, group)).toEqual(outcome(STATE, false, group));
      }),
      { seed: seedFor("SceneView.lazy against SceneView.of"), numRuns: 400 },
    );
  });

  it("answers as SceneView.of among enough bodies for the World's grid, near touching, radii mixed", () => {
    // 12 x 12 discs of radii 0.5 to 2 (the World answers from its grid from 64 bodies on), and
    // discs, moves, segments and points placed at a touching distance from one of them, give or
    // take a few ulps and OVERLAP_REL
    const radii = [0.5, 1, 2];
    const bodies = Array.from({ length: 144 }, (_, i) => ({
      id: `b${String(i).padStart(3, "0")}`,
      x: (i % 12) * 5,
      y: Math.floor(i / 12) * 5,
      r: radii[i % 3] as number,
      mu: 0,
    }));
    const crowd: ViewSource = { ...STATE, bodies, lines: [], points: [] };
    const nudge = fc.constantFrom(-1e-9, -4e-16, 0, 4e-16, 1e-9, 0.3);
    const place = fc
      .tuple(fc.integer({ min: 0, max: 143 }), fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }), nudge)
      .map(([k, angle, d]) => ({ near: bodies[k] as (typeof bodies)[number], angle, d }));
    const at = (p: { near: { x: number; y: number; r: number }; angle: number; d: number }, r: number) => {
      const dist = (p.near.r + r) * (1 + p.d);
      return [p.near.x + dist * Math.cos(p.angle), p.near.y + dist * Math.sin(p.angle)] as const;
    };
    const id = fc.constantFrom("n0", "n1", "b005", "b017");
    const action: fc.Arbitrary<Action> = fc.oneof(
      fc.tuple(id, place, fc.constantFrom(0.25, 1, 3)).map(([i, p, r]): Action => {
        const [x, y] = at(p, r);
        return { time: 2, type: "addBody", id: i, x, y, r, m: 1 };
      }),
      fc.tuple(id, place).map(([i, p]): Action => {
        const [x, y] = at(p, 1);
        return { time: 2, type: "updateBody", id: i, x, y, r: 1 };
      }),
      fc.tuple(id, place).map(([i, p]): Action => {
        const [x, y] = at(p, 0);
        return { time: 2, type: "addPoint", id: i, p: [x, y] };
      }),
      fc.tuple(id, place, fc.integer({ min: 1, max: 20 })).map(([i, p, len]): Action => {
        const [x, y] = at(p, 0);
        return { time: 2, type: "addLine", id: i, p1: [x, y], p2: [x + len, y], kind: "segment" };
      }),
      id.map((i): Action => ({ time: 2, type: "removeBody", id: i })),
    );
    fc.assert(
      fc.property(fc.array(action, { maxLength: 10 }), (group) => {
        expect(outcome(crowd, true, group)).toEqual(outcome(crowd, false, group));
      }),
      { seed: seedFor("SceneView.lazy among many bodies"), numRuns: 300 },
    );
  });
});
