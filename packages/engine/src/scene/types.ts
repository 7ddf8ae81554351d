/**
 * Scene file format v1: the types. A scene is a list of actions, each stamped with a time, over two
 * global fields (`g`: the friction field, `gravity`: a uniform acceleration field). The same types are
 * the Timeline's action list. Actions at the same time apply in list order.
 */

/** A 2D vector `[x, y]`. */
export type Vec2 = readonly [number, number];
/** Kind of a line obstacle: infinite `line`, `ray` from p1 through p2, or `segment` p1–p2. */
export type LineKind = "line" | "ray" | "segment";

/** How far to compute after an action or a prolong: seconds and/or events ahead (whichever comes
 *  first); neither = until no event is left. */
export interface Until {
  time?: number;
  events?: number;
}

/** One change to the scene at `time`. */
export type Action = { time: number; until?: Until } & (
  | { type: "addBody"; id: string; x: number; y: number; r: number; m: number; mu?: number; v?: Vec2 }
  | { type: "giveVelocity"; id: string; v: Vec2 }
  | { type: "updateBody"; id: string; x?: number; y?: number; v?: Vec2; r?: number; m?: number; mu?: number }
  | { type: "removeBody"; id: string }
  | { type: "addLine"; id: string; p1: Vec2; p2: Vec2; kind: LineKind }
  | { type: "updateLine"; id: string; p1?: Vec2; p2?: Vec2; kind?: LineKind }
  | { type: "removeLine"; id: string }
  | { type: "addPoint"; id: string; p: Vec2 }
  | { type: "updatePoint"; id: string; p: Vec2 }
  | { type: "removePoint"; id: string }
  | { type: "setGlobal"; g?: number; gravity?: Vec2 }
);

/** The type names of all actions. */
export type ActionType = Action["type"];

/** A scene file, version 1 (JSON). `meta` is free data for tools (view, title), kept as is. */
export interface SceneFile {
  format: "chapgame";
  version: 1;
  g: number;
  gravity: Vec2;
  actions: Action[];
  meta?: Record<string, unknown>;
}

/** Defaults of the format. */
export const SCENE_DEFAULTS = { g: 9.81, gravity: [0, 0] as Vec2, mu: 0, v: [0, 0] as Vec2 } as const;
