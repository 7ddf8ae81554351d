/**
 * Helpers of the timeline tests (not built, not published): small scenes and a fingerprint of
 * everything a timeline shows, for "nothing changed" checks.
 */
import type { Action, SceneFile } from "../scene/types.js";
import { Timeline } from "./timeline.js";

export const scene = (actions: Action[], g = 9.81): SceneFile => ({
  format: "chapgame",
  version: 1,
  g,
  gravity: [0, 0],
  actions,
});

/** A disc of radius 1 and mass 1 without friction. */
export const disc = (id: string, x: number, y: number, v: [number, number] = [0, 0], time = 0): Action => ({
  time,
  type: "addBody",
  id,
  x,
  y,
  r: 1,
  m: 1,
  mu: 0,
  v,
});

/** Everything observable about a timeline, for "nothing changed" checks. */
export function fingerprint(tl: Timeline): unknown {
  const times = [0, tl.horizon / 3, tl.horizon / 2, tl.horizon];
  return {
    scene: tl.toScene(),
    horizon: tl.horizon,
    counts: tl.counts(),
    log: tl.eventsBetween(0, tl.horizon),
    states: times.map((t) => tl.stateAt(t)),
    bytes: tl.historyBytes(),
  };
}

/** The README's example: a light disc between a wall and a heavy one, 31 collisions up to t = 20. */
export function wallAndHeavyDisc(): Timeline {
  const tl = new Timeline({ g: 0 });
  tl.apply({ time: 0, type: "addLine", id: "wall", p1: [0, -10], p2: [0, 10], kind: "line" });
  tl.apply({ time: 0, type: "addBody", id: "a", x: 5, y: 0, r: 1, m: 1 });
  tl.apply({ time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 100, v: [-1, 0] });
  tl.prolong({ time: 20 });
  return tl;
}
