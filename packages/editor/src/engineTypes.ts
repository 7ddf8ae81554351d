/**
 * The engine contract types the editor uses (docs/architecture.md), in one place so the rest of the
 * editor imports them from here. Timeline types not yet exported by the engine are copied here until they are.
 */
export type {
  Action,
  BodyState,
  EventKind,
  LineKind,
  LineState,
  PointState,
  SceneFile,
  Until,
  Vec2,
} from "@chapgame/engine";

import type { BodyState, EventKind, LineState, PointState, Vec2 } from "@chapgame/engine";

export interface LogEvent {
  time: number;
  type: EventKind | "action";
  ids: string[];
  point: Vec2 | null;
  normal: Vec2 | null;
  impulse: number | null;
}
export interface SceneState {
  time: number;
  g: number;
  gravity: Vec2;
  bodies: BodyState[];
  lines: LineState[];
  points: PointState[];
}
export interface Counts {
  bodyBody: number;
  bodyLine: number;
  bodyPoint: number;
  stop: number;
  action: number;
}
