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
 *  first); neither = until no event is left. Both are counted from where the computation starts,
 *  never absolute. */
export interface Until {
  /** Seconds to compute, counted from the action's `time` (an action's until) or from the horizon
   *  (`Timeline.prolong`): a duration, not an absolute time. A finite number >= 0. */
  time?: number | undefined;
  /** Collisions and stops to compute from there (actions not counted): a whole number >= 0, at
   *  most Number.MAX_SAFE_INTEGER. */
  events?: number | undefined;
}

/**
 * One change to the scene at `time`. Ids are non-empty strings, unique per kind (a body, a line
 * and a point may share one). Positions and coordinates are finite and at most 1e30 in size;
 * parseScene, checkAction and Timeline.apply refuse anything else with a SceneError naming the
 * field (`actions[3].r`, `action.v[0]`).
 */
export type Action = {
  /** When the action applies: an absolute time >= 0 on the timeline's clock (0 = the scene's
   *  start), at most TIME_MAX (1e30). Actions at the same time apply in list order, after the
   *  events at that time. */
  time: number;
  /** How far to compute after this action, counted from its `time`, not absolute. (Under the
   *  Timeline option `compute: false`, only an action given to `apply` has its until honoured.) */
  until?: Until | undefined;
} & (
  | {
      type: "addBody";
      id: string;
      /** Centre. */
      x: number;
      y: number;
      /** Radius, between 1e-30 and 1e30. */
      r: number;
      /** Mass: 1e-40 to 1e40, or Infinity (immovable by collisions; written "Infinity" in JSON). */
      m: number;
      /** Friction coefficient (default 0); must be 0 under a non-zero gravity field. Optional to
       *  write; every addBody the engine returns (parseScene, checkAction, Timeline.actions,
       *  toScene) has it, the default filled in. */
      mu?: number | undefined;
      /** Velocity [vx, vy] (default [0, 0]); each component 0 or at least 1e-30 in size. Optional
       *  to write; every addBody the engine returns has it, as `mu`. */
      v?: Vec2 | undefined;
    }
  | {
      type: "giveVelocity";
      id: string;
      /** The body's new velocity [vx, vy]. */
      v: Vec2;
    }
  | {
      /** Change a body; fields left out keep their values at the action's time. */
      type: "updateBody";
      id: string;
      x?: number | undefined;
      y?: number | undefined;
      /** New velocity [vx, vy]. */
      v?: Vec2 | undefined;
      r?: number | undefined;
      m?: number | undefined;
      mu?: number | undefined;
    }
  | { type: "removeBody"; id: string }
  | {
      type: "addLine";
      id: string;
      p1: Vec2;
      /** Must differ from p1. */
      p2: Vec2;
      /** `line` (infinite, through p1 and p2), `ray` (from p1 through p2) or `segment` (p1 to p2). */
      kind: LineKind;
    }
  | {
      type: "updateLine";
      id: string;
      p1?: Vec2 | undefined;
      p2?: Vec2 | undefined;
      kind?: LineKind | undefined;
    }
  | { type: "removeLine"; id: string }
  | { type: "addPoint"; id: string; p: Vec2 }
  | { type: "updatePoint"; id: string; p: Vec2 }
  | { type: "removePoint"; id: string }
  | {
      /** Change the friction field and/or the gravity field (left out: kept). */
      type: "setGlobal";
      g?: number | undefined;
      gravity?: Vec2 | undefined;
    }
);

/** The type names of all actions. */
export type ActionType = Action["type"];

/** A scene file, version 1 (JSON). `meta` is free data for tools (view, title), kept as is. */
export interface SceneFile {
  /** Always "chapgame". */
  format: "chapgame";
  /** The format version: 1. */
  version: 1;
  /** Friction field at time 0 (9.81 when the JSON leaves it out): a disc decelerates at mu·g. */
  g: number;
  /** Uniform acceleration field at time 0 ([0, 0] when the JSON leaves it out). */
  gravity: Vec2;
  /** The actions in file order; they apply in time order, ties in list order. */
  actions: Action[];
  /** Free data for tools (view, title), kept as is; must be an object. */
  meta?: Record<string, unknown> | undefined;
}

/** Defaults of the format. */
export const SCENE_DEFAULTS = { g: 9.81, gravity: [0, 0] as Vec2, mu: 0, v: [0, 0] as Vec2 } as const;
