/** Public data types of the Timeline (see docs/architecture.md). */
import type { ActionType, Vec2 } from "../scene/types.js";
import type { BodyState, EventKind, LineState, PointState } from "../sim/types.js";

/** Kind of a logged event: a collision, a stop, or an action. */
export type LogKind = EventKind | "action";

/** One logged event. For an action: ids = [the action's id] ([] for setGlobal), point/normal/impulse
 *  null, and `action` = the action's type (the whole action: Timeline.eventAction(i)). For a stop:
 *  point = where the body stopped, normal null, impulse 0. */
export interface LogEvent {
  time: number;
  type: LogKind;
  ids: string[];
  point: Vec2 | null;
  normal: Vec2 | null;
  impulse: number | null;
  /** Only on entries of type "action": what the action did (addBody, giveVelocity, removeLine, …). */
  action?: ActionType;
}

/** The exact state of the scene at one time; every list sorted by id. */
export interface SceneState {
  time: number;
  g: number;
  gravity: Vec2;
  bodies: BodyState[];
  lines: LineState[];
  points: PointState[];
}

export interface TimelineCounts {
  bodyBody: number;
  bodyLine: number;
  bodyPoint: number;
  stop: number;
  action: number;
}

export interface TimelineOptions {
  /** friction field (default 9.81) */
  g?: number | undefined;
  /** uniform acceleration field (default [0, 0]) */
  gravity?: Vec2 | undefined;
  /** false = headless: no event log, no keyframes, no time travel (stateAt only at the horizon) */
  history?: boolean | undefined;
  /** false = actions given to fromScene/setActions are only scheduled (applied when a prolong passes
   *  their time) and their `until`s are ignored; the caller drives with prolong/prolongSlice. */
  compute?: boolean | undefined;
}

export interface ProlongResult {
  events: number;
  reason: "time" | "events" | "idle";
}
