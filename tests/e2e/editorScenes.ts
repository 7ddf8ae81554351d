/**
 * Scenes the editor's end-to-end tests load or link to, written as scene files (format v1).
 */

/** One disc (`lonely`, r = 1, m = 1) at rest at the origin, no gravity: the smallest scene to fit. */
export const LONELY = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "lonely", x: 0, y: 0, r: 1, m: 1 }],
};

/** A scene file (format v1) of `actions`, with the friction field 9.81 and no gravity. */
export function sceneFile(actions: object[]): {
  format: string;
  version: number;
  g: number;
  gravity: number[];
  actions: object[];
} {
  return { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions };
}
