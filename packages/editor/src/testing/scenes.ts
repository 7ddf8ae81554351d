/**
 * Scene fixtures shared by the editor's tests.
 */
import type { Action, SceneFile } from "../engineTypes";

/** A version-1 scene of `actions` (friction field g, no gravity unless given). */
export function sceneOf(actions: Action[], g = 9.81, gravity: [number, number] = [0, 0]): SceneFile {
  return { format: "chapgame", version: 1, g, gravity, actions };
}

/** Discs of radius 1 and mass 1 at rest in a row, 10 apart from x = 0, one per id, added at t = 0. */
export function discsInRow(ids: readonly string[]): Action[] {
  return ids.map((id, i) => ({ time: 0, type: "addBody" as const, id, x: 10 * i, y: 0, r: 1, m: 1 }));
}

/** Discs "a" and "b" of discsInRow and a point "p1" at (5, 5), all at t = 0. */
export function twoDiscsAndPoint(): SceneFile {
  return sceneOf([...discsInRow(["a", "b"]), { time: 0, type: "addPoint", id: "p1", p: [5, 5] }]);
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

/**
 * Discs of radius 1 bouncing in a 100 × 100 box of segments, no friction: `discs` as [id, x, y,
 * v] (by default four, a to d, near a corner), then `later` (actions after t = 0, e.g. a disc
 * added at the centre, which an edit in the past can make invalid).
 */
export function boxScene(
  later: Action[],
  discs: [string, number, number, [number, number]][] = [
    ["a", 3, 3, [2, 1.3]],
    ["b", 10, 4, [-1.1, 2]],
    ["c", 15, 15, [0.7, -2.2]],
    ["d", 5, 12, [1.9, 0.4]],
  ],
): SceneFile {
  const wall = (id: string, p1: [number, number], p2: [number, number]): Action => ({
    time: 0,
    type: "addLine",
    id,
    p1,
    p2,
    kind: "segment",
  });
  return sceneOf(
    [
      wall("s", [0, 0], [100, 0]),
      wall("e", [100, 0], [100, 100]),
      wall("n", [100, 100], [0, 100]),
      wall("w", [0, 100], [0, 0]),
      ...discs.map(([id, x, y, v]): Action => ({ time: 0, type: "addBody", id, x, y, r: 1, m: 1, v })),
      ...later,
    ],
    0,
  );
}
