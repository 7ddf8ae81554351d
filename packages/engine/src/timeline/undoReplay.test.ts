/**
 * The undo of an edit computing forward without a copy of the World made up front (undoReplay.ts):
 * a scene built one action per apply copies no World per apply, and an apply refused after many
 * such applies (by its own checks, at a later instant after computing up to it, by a Zeno state in
 * its until, after a prolong that met a Zeno state) leaves the timeline exactly as a twin that never
 * saw it: the same log, states, bytes and, computed further, the same future, bit for bit.
 */
import { describe, expect, it, vi } from "vitest";
import { SceneError } from "../scene/errors.js";
import type { Action } from "../scene/types.js";
import { SimulationError } from "../sim/errors.js";
import { World } from "../sim/world.js";
import { CONVERGING_PAIR, coreInternals, coreOf, disc, fingerprint } from "./testSupport.js";
import { Timeline } from "./timeline.js";
import { UNDO_BASE_BODIES_PER_STEP } from "./undoReplay.js";

/** Bodies in every World copied while `run` runs. */
function copiedBodies(run: () => void): number {
  const clone = World.prototype.clone;
  let bodies = 0;
  const spy = vi.spyOn(World.prototype, "clone").mockImplementation(function (this: World) {
    bodies += this.bodyCount;
    return clone.call(this);
  });
  try {
    run();
  } finally {
    spy.mockRestore();
  }
  return bodies;
}

/** Cell i of a grid of boxes 3 wide, 4 apart: its four walls and two discs bouncing in it (their
 *  collisions with each other and the walls are the events). */
function cell(i: number, time: number): Action[] {
  const x = (i % 6) * 4;
  const y = Math.floor(i / 6) * 4;
  const wall = (id: string, p1: [number, number], p2: [number, number]): Action => ({
    time,
    type: "addLine",
    id: `${id}${i}`,
    p1,
    p2,
    kind: "segment",
  });
  const v = 1 + (i % 3) * 0.5;
  return [
    wall("l", [x - 1.5, y - 1.5], [x - 1.5, y + 1.5]),
    wall("r", [x + 1.5, y - 1.5], [x + 1.5, y + 1.5]),
    wall("b", [x - 1.5, y - 1.5], [x + 1.5, y - 1.5]),
    wall("t", [x - 1.5, y + 1.5], [x + 1.5, y + 1.5]),
    { ...disc(`a${i}`, x - 0.6, y - 0.2, [0.3, v], time), r: 0.4 } as Action,
    { ...disc(`b${i}`, x + 0.6, y + 0.2, [-v, 0.2], time), r: 0.4 } as Action,
  ];
}

/** A shelf with a disc on it, away from the cells: gravity pressing it there is a Zeno state. */
const SHELF: Action[] = [
  { time: 0, type: "addLine", id: "F", p1: [50, -1], p2: [60, -1], kind: "segment" },
  disc("f", 55, 0),
];

type Build = "one instant" | "successive instants";

/** The shelf, then 12 cells applied one action per call: all at time 0, or each cell 0.25 after the
 *  last, its last action with an until of 0.25 (colliding as they go). */
function build(history: boolean, how: Build): Timeline {
  const tl = new Timeline({ g: 0, history });
  for (const a of SHELF) tl.apply(a);
  for (let i = 0; i < 12; i++) {
    const t = how === "one instant" ? 0 : i * 0.25;
    const actions = cell(i, t);
    for (const [k, a] of actions.entries())
      tl.apply(
        how === "successive instants" && k === actions.length - 1 ? { ...a, until: { time: 0.25 } } : a,
      );
  }
  if (how === "one instant") tl.prolong({ time: 3 });
  return tl;
}

/** A still disc at (x, y) at time t. */
const still = (id: string, x: number, y: number, time: number): Action => disc(id, x, y, [0, 0], time);

/** Everything observable (without history: the horizon's state, counts and actions), and the core's
 *  internals. */
function seen(tl: Timeline): unknown {
  const inner = coreInternals(tl); // (before the readers settle an owed keyframe)
  if (tl.history) return { ...(fingerprint(tl) as object), inner };
  return {
    scene: tl.toScene(),
    horizon: tl.horizon,
    counts: tl.counts(),
    state: tl.stateAt(tl.horizon),
    inner,
  };
}

/** `tl` after a refused apply equals `twin`, now and after the same further edits. */
function expectAsTwin(tl: Timeline, twin: Timeline): void {
  expect(seen(tl)).toStrictEqual(seen(twin));
  for (const t of [tl, twin]) {
    t.apply(still("z", 0, 50, t.horizon + 0.5));
    t.apply({ time: t.horizon + 1, type: "giveVelocity", id: "a3", v: [2, -1.5], until: { time: 4 } });
  }
  expect(seen(tl)).toStrictEqual(seen(twin));
}

function refused(f: () => void, kind: typeof SceneError | typeof SimulationError): void {
  let error: unknown = null;
  try {
    f();
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(kind);
}

const cases: [boolean, Build][] = [
  [true, "one instant"],
  [true, "successive instants"],
  [false, "one instant"],
  [false, "successive instants"],
];

describe.each(cases)("history %s, discs applied one per call at %s", (history, how) => {
  it("a disc overlapping one at the horizon is refused by its checks: nothing changes", () => {
    const tl = build(history, how);
    const twin = build(history, how);
    const at = tl.stateAt(tl.horizon).bodies.find((b) => b.id === "d7");
    refused(() => tl.apply(still("y", at?.x ?? 0, at?.y ?? 0, tl.horizon)), SceneError);
    expectAsTwin(tl, twin);
  });

  it("a disc refused at a later instant, after computing up to it: nothing changes", () => {
    const tl = build(history, how);
    const twin = build(history, how);
    const h = tl.horizon;
    // b5 is there at h + 2 (the twin says where)
    twin.prolongTo(h + 2);
    const at = twin.stateAt(h + 2).bodies.find((b) => b.id === "b5");
    const twin2 = build(history, how);
    refused(() => tl.apply(still("y", at?.x ?? 0, at?.y ?? 0, h + 2)), SceneError);
    expect(tl.horizon).toBe(h);
    expectAsTwin(tl, twin2);
  });

  it("an until that meets a Zeno state: nothing changes", () => {
    const tl = build(history, how);
    const twin = build(history, how);
    const t = tl.horizon + 0.5;
    refused(
      () => tl.apply({ time: t, type: "setGlobal", gravity: [0, -1], until: { time: 1 } }),
      SimulationError,
    );
    expectAsTwin(tl, twin);
  });
});

describe("an apply refused after a prolong met a Zeno state", () => {
  it.each([true, false])("history %s: the World where the prolong stopped is given back", (history) => {
    const make = () => {
      // (timeline.test.ts: collisions and stops converge geometrically to t ≈ 52.249)
      const tl = new Timeline({ g: 0.5, history });
      for (const a of CONVERGING_PAIR) tl.apply(a);
      expect(() => tl.prolong({ time: 60 })).toThrow(SimulationError);
      return tl;
    };
    const tl = make();
    const twin = make();
    expect(coreOf(tl).settled).toBe(false);
    refused(() => tl.apply(still("c", 20, 20, tl.horizon)), SimulationError);
    refused(() => tl.apply(still("c", 20, 20, tl.horizon + 1)), SimulationError);
    expect(seen(tl)).toStrictEqual(seen(twin));
    // given back by its copy: a recomputation would have met the Zeno state again
    expect(coreOf(tl).settled).toBe(false);
    expect(() => tl.prolong({ time: 5 })).toThrow(SimulationError);
    expect(() => twin.prolong({ time: 5 })).toThrow(SimulationError);
    expect(seen(tl)).toStrictEqual(seen(twin));
  });
});

describe("a scene built one disc per apply copies no World per apply", () => {
  const n = 400;
  const at = (i: number, time: number): Action => still(`s${i}`, (i % 20) * 3, Math.floor(i / 20) * 3, time);
  const builds: [string, (tl: Timeline) => void][] = [
    [
      "at one instant",
      (tl) => {
        for (let i = 0; i < n; i++) tl.apply(at(i, 0));
      },
    ],
    [
      "at successive instants",
      (tl) => {
        for (let i = 0; i < n; i++) tl.apply({ ...at(i, i * 0.01), until: { time: 0.005 } });
      },
    ],
  ];

  it.each(builds)("with history, %s: none", (_, run) => {
    const tl = new Timeline();
    expect(copiedBodies(() => run(tl))).toBe(0);
    expect(tl.stateAt(tl.horizon).bodies.length).toBe(n);
  });

  it.each(builds)(
    "without history, %s: copies of a linear number of bodies in all (an undo base now and then)",
    (_, run) => {
      const tl = new Timeline({ history: false });
      const copied = copiedBodies(() => run(tl));
      // a copy once the last is bodies / UNDO_BASE_BODIES_PER_STEP actions old: a geometric series
      expect(copied).toBeGreaterThan(0);
      expect(copied).toBeLessThanOrEqual((UNDO_BASE_BODIES_PER_STEP + 2) * n);
      expect(tl.stateAt(tl.horizon).bodies.length).toBe(n);
    },
  );
});

describe("an apply whose until reaches a scheduled action it makes invalid (compute: false)", () => {
  it.each([true, false])("history %s: refused, nothing changes", (history) => {
    const make = () => {
      const tl = new Timeline({ g: 0, history, compute: false });
      const actions: Action[] = [];
      for (let i = 0; i < 6; i++) actions.push(...cell(i, 0));
      actions.push(still("late", 30, 30, 2));
      tl.setActions(actions);
      tl.prolongTo(1.5);
      return tl;
    };
    const tl = make();
    const twin = make();
    // a disc where "late" will be added at t = 2, moving off after it: that addBody overlaps it
    const doomed: Action = { ...disc("z", 30, 30, [0.1, 0], 1.5), until: { time: 1 } };
    expect(() => tl.apply(doomed)).toThrow(/actions\[\d+\].*once this action is in place/);
    expect(seen(tl)).toStrictEqual(seen(twin));
    for (const t of [tl, twin]) t.prolongTo(4);
    expect(seen(tl)).toStrictEqual(seen(twin));
  });
});
