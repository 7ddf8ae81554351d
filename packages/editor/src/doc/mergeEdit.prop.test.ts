// Property: a series of edits of one body at one instant, merged as the editor merges them
// (mergeEdit.ts), gives the future the separate actions give, bit for bit, but for the one case
// its header names: the merged action changes nothing (changesNothing, which the host then drops),
// and the future is the scene's without it, bit for bit.
// Edits at the instant of a collision (MEET: a meets b) and just before it are among the times.
import { Timeline } from "@chapgame/engine";
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "../engineTypes";
import { seedFor } from "../testing/seed";
import { changesNothing, mergedEdit } from "./mergeEdit";

const SEED = seedFor("mergeEdit.prop.test", 20261124);

/** Three discs in a box: a and b meet at MEET (about 3.86). */
const BOX: Action[] = [
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0.3] },
  { time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 2, v: [-1, 0] },
  { time: 0, type: "addBody", id: "c", x: 5, y: 6, r: 0.5, m: 1, v: [0, -1] },
  { time: 0, type: "addLine", id: "e", p1: [20, -50], p2: [20, 50], kind: "line" },
  { time: 0, type: "addLine", id: "w", p1: [-20, -50], p2: [-20, 50], kind: "line" },
  { time: 0, type: "addLine", id: "s", p1: [-50, -20], p2: [50, -20], kind: "line" },
  { time: 0, type: "addLine", id: "n", p1: [-50, 20], p2: [50, 20], kind: "line" },
];
const scene = (actions: readonly Action[]): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [...actions],
});
const END = 30;

/** The time of BOX's first collision (a meets b), read from its log. */
const MEET = (() => {
  const tl = Timeline.fromScene(scene(BOX), { compute: false });
  tl.prolongTo(5);
  return tl.eventsBetween(0, 5).find((e) => e.type === "bodyBody")!.time;
})();

/** The state at END of `actions`, or the error computing it gives. */
function future(actions: readonly Action[]): string {
  const tl = Timeline.fromScene(scene(actions), { compute: false });
  try {
    tl.prolongTo(END);
  } catch (e) {
    return String(e);
  }
  return JSON.stringify(tl.stateAt(END));
}

const edit = (time: number, id: string): fc.Arbitrary<Action> =>
  fc.oneof(
    fc
      .tuple(fc.integer({ min: -20, max: 20 }), fc.integer({ min: -20, max: 20 }))
      .map(([vx, vy]): Action => ({ time, type: "giveVelocity", id, v: [vx / 10, vy / 10] })),
    fc.integer({ min: -15, max: 15 }).map((x): Action => ({ time, type: "updateBody", id, x })),
    fc.integer({ min: -15, max: 15 }).map((y): Action => ({ time, type: "updateBody", id, y })),
    fc.integer({ min: 1, max: 3 }).map((m): Action => ({ time, type: "updateBody", id, m })),
  );

const series = fc
  .tuple(fc.constantFrom(0, MEET - 0.001, MEET, 7.5, 12), fc.constantFrom("a", "b", "c"))
  .chain(([time, id]) => fc.array(edit(time, id), { minLength: 2, maxLength: 4 }));

describe("merged edits of one body at one instant", () => {
  it("property: the future of the separate actions, or, when the merged action changes nothing, of the scene without it", () => {
    fc.assert(
      fc.property(series, (edits) => {
        // the separate actions as the engine takes them; a series it refuses is no case
        let separate: Action[] = BOX;
        for (const e of edits) {
          const tl = Timeline.fromScene(scene(separate), { compute: false });
          try {
            tl.apply(e, { keepHorizon: false, checkLater: false });
          } catch {
            return;
          }
          separate = tl.actions.slice() as Action[];
        }
        let merged: Action[] = BOX;
        for (const e of edits) {
          const m = mergedEdit(merged, e);
          merged = m === null ? [...merged, e] : merged.map((a, i) => (i === m.index ? m.action : a));
        }
        expect(merged.length).toBe(BOX.length + 1); // all merged into the first edit (or the add at 0)
        const got = future(merged);
        // the merged action (or the add it changed) and the scene without it, at its instant
        const last = merged.at(-1) as Action;
        const mergedAction = BOX.includes(last) ? null : last;
        const without = merged.filter((a) => a !== mergedAction);
        const tl = Timeline.fromScene(scene(without), { compute: false });
        tl.prolongTo(edits[0]!.time);
        if (mergedAction !== null && changesNothing(mergedAction, tl.stateAt(edits[0]!.time)))
          expect(got).toBe(future(without));
        else expect(got).toBe(future(separate));
      }),
      { seed: SEED, numRuns: 150 },
    );
  });
});

describe("changesNothing at a collision's instant", () => {
  it("reads the velocity the collision gave, as the engine's own no-change check does", () => {
    const at = (t: number) => {
      const tl = Timeline.fromScene(scene(BOX), { compute: false });
      tl.prolongTo(t);
      return tl.stateAt(t);
    };
    const state = at(MEET);
    const a = state.bodies.find((b) => b.id === "a")!;
    expect([a.vx, a.vy]).not.toEqual([1, 0.3]); // the collision has turned a
    const same: Action = { time: MEET, type: "giveVelocity", id: "a", v: [a.vx, a.vy] };
    const old: Action = { time: MEET, type: "giveVelocity", id: "a", v: [1, 0.3] };
    expect(changesNothing(same, state)).toBe(true);
    expect(future([...BOX, same])).toBe(future(BOX));
    expect(changesNothing(old, state)).toBe(false);
    expect(future([...BOX, old])).not.toBe(future(BOX));
  });
});
