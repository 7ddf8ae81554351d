/**
 * TEMPORARY development fake of the engine Timeline (constant-velocity motion, no collisions).
 * Deleted when @chapgame/engine exports the real Timeline.
 */
import type { Action, BodyState, LogEvent, SceneFile, SceneState, Until } from "../engineTypes";
import type { TimelineLike } from "./timelineLike";

class FakeSceneError extends Error {
  constructor(
    readonly path: string,
    reason: string,
  ) {
    super(`${path}: ${reason}`);
  }
}

export function fakeTimeline(scene: SceneFile): TimelineLike {
  let actions: Action[] = [];
  let horizon = 0;
  const check = (list: Action[]) => {
    list.forEach((a, i) => {
      if ("r" in a && a.r !== undefined && !(a.r > 0))
        throw new FakeSceneError(`actions[${i}].r`, "must be a positive finite number");
      if ("x" in a && a.x !== undefined && !Number.isFinite(a.x))
        throw new FakeSceneError(`actions[${i}].x`, "must be a finite number");
    });
  };
  const stateAt = (t: number): SceneState => {
    const bodies = new Map<string, BodyState>();
    let tPrev = 0;
    const move = (to: number) => {
      for (const b of bodies.values()) {
        b.x += b.vx * (to - tPrev);
        b.y += b.vy * (to - tPrev);
      }
      tPrev = to;
    };
    for (const a of actions) {
      if (a.time > t) break;
      move(a.time);
      if (a.type === "addBody") {
        const v = a.v ?? [0, 0];
        bodies.set(a.id, {
          id: a.id,
          x: a.x,
          y: a.y,
          vx: v[0],
          vy: v[1],
          ax: 0,
          ay: 0,
          r: a.r,
          m: a.m,
          mu: a.mu ?? 0,
        });
      } else if (a.type === "giveVelocity" || a.type === "updateBody") {
        const b = bodies.get(a.id);
        if (b) {
          if ("x" in a && a.x !== undefined) b.x = a.x;
          if ("y" in a && a.y !== undefined) b.y = a.y;
          if (a.v) [b.vx, b.vy] = a.v;
          if ("r" in a && a.r !== undefined) b.r = a.r;
        }
      } else if (a.type === "removeBody") bodies.delete(a.id);
    }
    move(t);
    return {
      time: t,
      g: scene.g,
      gravity: scene.gravity,
      bodies: [...bodies.values()].sort((p, q) => (p.id < q.id ? -1 : 1)),
      lines: [],
      points: [],
    };
  };
  const log = (): LogEvent[] =>
    actions.map((a) => ({
      time: a.time,
      type: "action",
      ids: "id" in a ? [a.id] : [],
      point: null,
      normal: null,
      impulse: null,
    }));
  const setActions = (list: readonly Action[]) => {
    const next = [...list].sort((p, q) => p.time - q.time);
    check(next);
    actions = next;
  };
  setActions(scene.actions);
  horizon = 10;
  return {
    get actions() {
      return actions;
    },
    get horizon() {
      return horizon;
    },
    get eventCount() {
      return actions.length;
    },
    apply(a: Action) {
      setActions([...actions, a]);
      horizon = Math.max(horizon, a.time);
    },
    setActions,
    prolongSlice(until: Until) {
      horizon += until.time ?? 10;
      return { done: true, events: 0, horizon };
    },
    stateAt,
    nextEventTime: (t) => log().find((e) => e.time > t)?.time ?? null,
    prevEventTime: (t) =>
      log()
        .reverse()
        .find((e) => e.time < t)?.time ?? null,
    event: (i) => log()[i]!,
    counts: () => ({ bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0, action: actions.length }),
    historyBytes: () => 0,
    toScene: () => ({ ...scene, actions: [...actions] }),
  };
}
