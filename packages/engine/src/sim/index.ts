/** Barrel of src/sim: the public exports of the simulation. */
export type { BodyArrays } from "./bodyArrays.js";
export { ChapgameError, SimulationError } from "./errors.js";
export type { LineKind } from "./obstacles.js";
export type {
  AdvanceLimits,
  AdvanceResult,
  BodyInit,
  BodyMotion,
  BodyMotionInit,
  BodyPatch,
  BodyState,
  EventCounts,
  EventKind,
  LineState,
  Optimizations,
  PointState,
  Vec2,
  WorldCollision,
  WorldEvent,
  WorldOptions,
  WorldStop,
} from "./types.js";
export { World } from "./world.js";
