/**
 * Scene fixtures shared by the editor's tests.
 */
import type { Action, SceneFile } from "../engineTypes";

/** A version-1 scene of `actions` (friction field g, no gravity unless given). */
export function sceneOf(actions: Action[], g = 9.81, gravity: [number, number] = [0, 0]): SceneFile {
  return { format: "chapgame", version: 1, g, gravity, actions };
}

/**
 * An immovable disc crushes a small one against a wall: collisions pile up before t = 2 and the
 * engine stops with a Zeno state (what the editor must report, not hang on).
 */
export function crushScene(): SceneFile {
  return {
    format: "chapgame",
    version: 1,
    g: 9.81,
    gravity: [0, 0],
    actions: [
      { time: 0, type: "addLine", id: "wall", p1: [0, -5], p2: [0, 5], kind: "line" },
      { time: 0, type: "addBody", id: "small", x: 2, y: 0, r: 1, m: 1 },
      { time: 0, type: "addBody", id: "crusher", x: 5, y: 0, r: 1, m: Number.POSITIVE_INFINITY, v: [-1, 0] },
    ],
  };
}

/** One disc of radius 1 at the origin, at rest: the smallest scene to open, drop or fit. */
export function loneDiscScene(): SceneFile {
  return {
    format: "chapgame",
    version: 1,
    g: 9.81,
    gravity: [0, 0],
    actions: [{ time: 0, type: "addBody", id: "lonely", x: 0, y: 0, r: 1, m: 1 }],
  };
}
