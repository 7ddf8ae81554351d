// A Timeline of a scene with many segments and pegs: built from the scene file (one group of actions
// at time 0), one apply at a time, or from the same actions in another order, it logs the same
// events and states, bit for bit; removals and updates in the middle of the list at a later time
// too, and the World rebuilt from a keyframe after them continues as the one that made them. A
// line added through several bodies is refused naming the smallest id, whatever their order.
import { describe, expect, it } from "vitest";
import { maze, shuffled } from "../../test/obstacleScene.js";
import { parseScene } from "../scene/parse.js";
import type { Action } from "../scene/types.js";
import { disc, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** The maze as actions at time 0: walls, pegs, discs. */
function mazeActions(seed: number): Action[] {
  const m = maze(seed, 16, 400, 6);
  return [
    ...m.walls.map(
      (l): Action => ({ time: 0, type: "addLine", id: l.id, p1: l.p1, p2: l.p2, kind: "segment" }),
    ),
    ...m.pegs.map((p): Action => ({ time: 0, type: "addPoint", id: p.id, p: p.p })),
    ...m.discs.map((d) => disc(d.id, d.x, d.y, [d.vx, d.vy])),
  ];
}

/** The collisions and stops a timeline logged up to `t` (not its actions, logged in list order). */
const collisions = (tl: Timeline, t: number) => tl.eventsBetween(0, t).filter((e) => e.type !== "action");

/** What a timeline computed up to `t`: its counts, collisions and states. */
function computed(tl: Timeline, t: number): unknown {
  tl.prolongTo(t);
  return {
    counts: tl.counts(),
    log: collisions(tl, t),
    states: [0, t / 4, t / 2, t].map((u) => tl.stateAt(u)),
  };
}

describe("a Timeline of many obstacles", () => {
  const actions = mazeActions(9);
  const expected = computed(Timeline.fromScene(scene(actions, 0)), 30);

  it("logs many collisions with walls and pegs", () => {
    const counts = (expected as { counts: { bodyLine: number; bodyPoint: number } }).counts;
    expect(counts.bodyLine).toBeGreaterThan(100);
    expect(counts.bodyPoint).toBeGreaterThan(10);
  });

  it("from the scene file, one apply at a time, or the actions in another order: the same", () => {
    const oneByOne = new Timeline({ g: 0 });
    for (const a of actions) oneByOne.apply(a);
    expect(computed(oneByOne, 30)).toEqual(expected);
    for (const seed of [1, 2]) {
      const tl = Timeline.fromScene(scene(shuffled(actions, seed), 0));
      expect(computed(tl, 30)).toEqual(expected);
    }
    const headless = Timeline.fromScene(scene(shuffled(actions, 3), 0), { history: false });
    headless.prolongTo(30);
    expect(headless.stateAt(30)).toEqual((expected as { states: unknown[] }).states[3]);
  });

  it("removals and updates in the middle of the list at a later time, in any order", () => {
    const walls = actions.filter((a): a is Action & { type: "addLine" } => a.type === "addLine");
    const middle = walls.slice(walls.length / 3, (2 * walls.length) / 3);
    const edits: Action[] = middle.flatMap((l, k): Action[] => {
      if (k % 3 === 0) return [{ time: 10, type: "removeLine", id: l.id }];
      if (k % 4 === 0) return [{ time: 10, type: "updateLine", id: l.id, kind: "ray" }];
      return [];
    });
    const pegs = actions.filter((a) => a.type === "addPoint").slice(100, 200);
    edits.push(...pegs.map((p): Action => ({ time: 10, type: "removePoint", id: (p as { id: string }).id })));
    const inOrder = Timeline.fromScene(scene([...actions, ...edits], 0));
    const want = computed(inOrder, 30);
    const other = Timeline.fromScene(scene(shuffled([...actions, ...edits], 4), 0));
    expect(computed(other, 30)).toEqual(want);
    // The edits change the history after t = 10, not before.
    const w = want as { states: unknown[]; log: { time: number }[] };
    const e = expected as typeof w;
    expect(w.states[1]).toEqual(e.states[1]);
    expect(w.states[3]).not.toEqual(e.states[3]);
    // An action after the removals restarts the history from the keyframe before it: the World
    // is rebuilt from that keyframe's lines, points and motions (lines and points in id order, not
    // the order they were added in) and must compute the same future. The action gives d0 the
    // velocity it has then, which changes nothing (World.updateBody keeps the motion).
    const restarted = Timeline.fromScene(scene([...actions, ...edits], 0));
    restarted.prolongTo(30);
    const d0 = restarted.stateAt(20).bodies.find((b) => b.id === "d0");
    restarted.apply({ time: 20, type: "giveVelocity", id: "d0", v: [d0?.vx ?? 0, d0?.vy ?? 0] });
    restarted.prolongTo(30);
    expect(w.log.filter((x) => x.time > 20).length).toBeGreaterThan(20);
    expect(collisions(restarted, 30)).toEqual(w.log);
    expect(restarted.stateAt(30)).toEqual(w.states[3]);
  });
});

describe("a line added through several bodies, in a scene file or a Timeline", () => {
  it("names the smallest id, whatever order the bodies were added in", () => {
    const bodies = [disc("z", 0, 0), disc("n", 10, 0), disc("b", 20, 0)];
    for (const order of [bodies, [...bodies].reverse(), shuffled(bodies, 5)]) {
      const line: Action = { time: 0, type: "addLine", id: "cut", p1: [-5, 0], p2: [25, 0], kind: "segment" };
      expect(() => parseScene(scene([...order, line]))).toThrow(
        'actions[3]: line "cut" would overlap body "b" at time 0',
      );
      const tl = Timeline.fromScene(scene(order, 0));
      expect(() => tl.apply({ ...line, p2: [15, 0] })).toThrow(
        'action: line "cut" would overlap body "n" at time 0',
      );
      expect(() => tl.apply({ time: 0, type: "addPoint", id: "pin", p: [20.5, 0] })).toThrow(
        'action: point "pin" would overlap body "b" at time 0',
      );
    }
  });
});
