/**
 * A scene built one action per call at successive instants (an editor adding discs at different
 * times, a game spawning a body every frame): the scene rules ask the World for the bodies near an
 * added disc (scene/sceneView.ts) and the keyframe after each instant's action is a delta of the one
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

const RUNS = Number(process.env.RUNS ?? 40);
const coord = num(0, 16);

/** What an action at an instant does (ids are given by the builder). */
type Step =
  | { kind: "add"; x: number; y: number; r: number; v: [number, number]; mu: number }
  | { kind: "push"; who: number; v: [number, number] }
  | { kind: "move"; who: number; x: number; y: number }
  | { kind: "remove"; who: number }
  | { kind: "point"; x: number; y: number };

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
);

/** The action of step k at time t; `ids` are the bodies added so far (the caller adds this one's). */
function actionOf(s: Step, k: number, t: number, ids: string[]): Action {
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
  }
}

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
        (steps, dt, g) => {
          const tl = new Timeline({ g });
          const headless = new Timeline({ g, history: false });
          const ids: string[] = [];
          const times: number[] = [];
          const seen: SceneState[] = [];
          steps.forEach((s, k) => {
            const t = k * dt;
            const a = actionOf(s, k, t, ids);
            tl.prolongTo(t);
            headless.prolongTo(t);
            const expected = wholeStateOutcome(tl.stateAt(t), a);
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
          const end = (steps.length - 1) * dt + dt / 2;
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
