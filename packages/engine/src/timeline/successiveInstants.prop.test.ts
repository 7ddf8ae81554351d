/**
 * A scene built one action per call at successive instants (an editor adding discs at different
 * times, a game spawning a body every frame): the scene rules ask the World for the bodies near an
 * added disc (scene/sceneView.ts: among a crowd, from its grid) and the keyframe after each instant's action is a delta of the one
 * before (keyframeDelta.ts). Everything observable is what reading every body and copying every
 * body gave: each refusal is the one a view of the whole state at that time gives, each state read
 * afterwards is the one a timeline without history (no keyframes) showed at that time, and the log,
 * states, arrays, paths and event details are those of the same actions given in one setActions,
 * also after an edit in the past (a restart from a delta) and after forgetBefore.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { checkAction } from "../scene/action.js";
import { checkAndApply, SceneView } from "../scene/sceneRules.js";
import type { Action } from "../scene/types.js";
import { expectSameAsStateAt, expectSameKept, num, seedFor, speed } from "./testSupport.js";
import { Timeline } from "./timeline.js";
import type { SceneState } from "./types.js";

const RUNS = Number(process.env.RUNS ?? 30);
const coord = num(0, 16);

/** What an action at an instant does (ids are given by the builder). */
type Step =
  | { kind: "add"; x: number; y: number; r: number; v: [number, number]; mu: number }
  | { kind: "push"; who: number; v: [number, number] }
  | { kind: "move"; who: number; x: number; y: number }
  | { kind: "remove"; who: number }
  | { kind: "point"; x: number; y: number }
  | { kind: "touch"; who: number; angle: number; d: number; r: number };

const step: fc.Arbitrary<Step> = fc.oneof(
  {
    weight: 6,
    arbitrary: fc.record({
      kind: fc.constant("add" as const),
      x: coord,
      y: coord,
      r: fc.constantFrom(0.5, 1, 1.5),
      v: fc.tuple(speed, speed),
      mu: fc.constantFrom(0, 0, 0.2),
    }),
  },
  {
    weight: 1,
    arbitrary: fc.record({ kind: fc.constant("push" as const), who: fc.nat(), v: fc.tuple(speed, speed) }),
  },
  {
    weight: 1,
    arbitrary: fc.record({ kind: fc.constant("move" as const), who: fc.nat(), x: coord, y: coord }),
  },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant("remove" as const), who: fc.nat() }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant("point" as const), x: coord, y: coord }) },
  {
    // a disc put against a body where it is now, touching give or take a few ulps and OVERLAP_REL
    weight: 3,
    arbitrary: fc.record({
      kind: fc.constant("touch" as const),
      who: fc.nat(),
      angle: num(0, 2 * Math.PI),
      d: fc.constantFrom(-2e-9, -1e-9, -4e-16, 0, 4e-16, 1e-9),
      r: fc.constantFrom(0.5, 1),
    }),
  },
);

/** The action of step k at time t in state `now`; `ids` are the bodies added so far (the caller adds
 *  this one's). */
function actionOf(s: Step, k: number, t: number, ids: string[], now: SceneState): Action {
  const who = (n: number) => ids[n % Math.max(1, ids.length)] ?? "none";
  switch (s.kind) {
    case "add":
      return { time: t, type: "addBody", id: `d${k}`, x: s.x, y: s.y, r: s.r, m: 1, mu: s.mu, v: s.v };
    case "push":
      return { time: t, type: "giveVelocity", id: who(s.who), v: s.v };
    case "move":
      return { time: t, type: "updateBody", id: who(s.who), x: s.x, y: s.y };
    case "remove":
      return { time: t, type: "removeBody", id: who(s.who) };
    case "point":
      return { time: t, type: "addPoint", id: `p${k}`, p: [s.x, s.y] };
    case "touch": {
      const b = now.bodies[s.who % Math.max(1, now.bodies.length)];
      const at = b === undefined ? 0 : (b.r + s.r) * (1 + s.d);
      const [x, y] = b === undefined ? [0, 0] : [b.x + at * Math.cos(s.angle), b.y + at * Math.sin(s.angle)];
      return { time: t, type: "addBody", id: `d${k}`, x, y, r: s.r, m: 1 };
    }
  }
}

/** 81 discs on a lattice with gaps of 1, moving at up to 1.4 units/s, at t = 0. */
const CROWD: Action[] = Array.from({ length: 81 }, (_, i) => ({
  time: 0,
  type: "addBody",
  id: `c${String(i).padStart(2, "0")}`,
  x: (i % 9) * 3,
  y: Math.floor(i / 9) * 3,
  r: 1,
  m: 1,
  v: [(((i * 7) % 5) - 2) / 2, (((i * 3) % 5) - 2) / 2],
}));

/** "ok", or the refusal's message. */
function outcome(f: () => void): string {
  try {
    f();
    return "ok";
  } catch (e) {
    return (e as Error).message;
  }
}

/** The refusal a view of the whole state `s` gives action `a` (the scene rules before the lazy view). */
function wholeStateOutcome(s: SceneState, a: Action): string {
  return outcome(() => checkAndApply(SceneView.of(s), checkAction(a, "action"), "action"));
}

describe("actions applied one per call at successive instants", () => {
  it("refuse, log and read as a whole-state check, a timeline without history and one setActions do", () => {
    fc.assert(
      fc.property(
        fc.array(step, { minLength: 1, maxLength: 30 }),
        fc.constantFrom(0.01, 0.3, 1),
        fc.constantFrom(0, 1),
        fc.boolean(),
        (steps, dt, g, crowded) => {
          const tl = new Timeline({ g });
          const headless = new Timeline({ g, history: false });
          // a crowd first (81 moving discs: the World answers the scene rules from its grid), or none
          const crowd = crowded ? CROWD : [];
          tl.setActions(crowd);
          headless.setActions(crowd);
          const start = crowded ? dt : 0;
          const ids: string[] = [];
          const times: number[] = [];
          const seen: SceneState[] = [];
          steps.forEach((s, k) => {
            const t = start + k * dt;
            tl.prolongTo(t);
            headless.prolongTo(t);
            const now = tl.stateAt(t);
            const a = actionOf(s, k, t, ids, now);
            const expected = wholeStateOutcome(now, a);
            const got = outcome(() => tl.apply(a));
            expect(got).toBe(expected);
            expect(outcome(() => headless.apply(a))).toBe(got);
            if (got === "ok" && a.type === "addBody") ids.push(a.id);
            // the states at the action's instant and between instants, read from the World
            times.push(t);
            seen.push(headless.stateAt(t));
            headless.prolongTo(t + dt / 2);
            times.push(t + dt / 2);
            seen.push(headless.stateAt(t + dt / 2));
          });
          const end = start + (steps.length - 1) * dt + dt / 2;
          tl.prolongTo(end);
          times.forEach((t, k) => {
            expect(tl.stateAt(t)).toStrictEqual(seen[k]);
          });
          const whole = new Timeline({ g });
          whole.setActions(tl.actions);
          whole.prolongTo(end);
          const same = () => {
            expect(tl.eventRange(0, Number.POSITIVE_INFINITY)).toStrictEqual(
              whole.eventRange(0, Number.POSITIVE_INFINITY),
            );
            expect(tl.counts()).toStrictEqual(whole.counts());
            for (const t of times) {
              const s = tl.stateAt(t);
              expect(s).toStrictEqual(whole.stateAt(t));
              expectSameAsStateAt(tl.bodyArraysAt(t), s);
            }
            for (const id of ids) expect(tl.path(id)).toStrictEqual(whole.path(id));
            for (let i = 0; i < tl.eventCount; i++)
              expect(tl.eventDetail(i)).toStrictEqual(whole.eventDetail(i));
          };
          same();
          // an edit in the past restarts from a keyframe after an instant's action (a delta)
          const mid = times[Math.floor(times.length / 2)] as number;
          const push: Action = { time: mid, type: "giveVelocity", id: ids[0] ?? "none", v: [1, 1] };
          expect(outcome(() => tl.apply(push))).toBe(outcome(() => whole.apply(push)));
          same();
          // the start forgotten: the first kept keyframe holds its bodies in full
          const twin = new Timeline({ g });
          twin.setActions(tl.actions);
          twin.prolongTo(tl.horizon);
          tl.forgetBefore(mid);
          expectSameKept(
            tl,
            twin,
            times.filter((t) => t >= tl.historyStart),
          );
        },
      ),
      { seed: seedFor("one action per call at successive instants"), numRuns: RUNS },
    );
  });
});

describe("a disc added at a new instant against a crowd", () => {
  it("is checked with the scene's rounding: a pair only the World's own check calls an overlap passes the scene rules", () => {
    // 0.5 + 1 apart give or take an ulp: d² < (r1 + r2)² (1 - OVERLAP_REL)² is false, the World's
    // d² < ((r1 + r2)(1 - OVERLAP_REL))² is true; 80 more discs far off (the World answers from its grid)
    const far: Action[] = Array.from({ length: 80 }, (_, i) => ({
      time: 0,
      type: "addBody",
      id: `f${i}`,
      x: 100 + (i % 9) * 3,
      y: Math.floor(i / 9) * 3,
      r: 1,
      m: 1,
    }));
    const close: Action = {
      time: 1,
      type: "addBody",
      id: "n",
      x: 0.6803941814579717,
      y: 1.336811038755342,
      r: 0.5,
      m: 1,
    };
    for (const history of [true, false]) {
      const tl = new Timeline({ g: 0, history });
      tl.setActions([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }, ...far]);
      tl.prolongTo(1);
      expect(wholeStateOutcome(tl.stateAt(1), close)).toBe("ok");
      expect(outcome(() => tl.apply(close))).toBe('action.x: the body would overlap body "a"');
    }
  });
});
