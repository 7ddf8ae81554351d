/**
 * The part of the engine's Timeline the editor's worker uses (docs/architecture.md), so the host can
 * be tested with the real Timeline and typed without depending on its private members.
 */
import type {
  Action,
  BodyArrays,
  Counts,
  EventDetail,
  LogEvent,
  PathPiece,
  SceneFile,
  SceneState,
  Until,
} from "../engineTypes";

export interface TimelineLike {
  readonly actions: readonly Action[];
  readonly horizon: number;
  readonly eventCount: number;
  apply(action: Action, options?: { keepHorizon?: boolean; checkLater?: boolean }): void;
  setActions(actions: readonly Action[]): void;
  prolongSlice(until: Until, budget: number): { done: boolean; events: number; horizon: number };
  prolongTo(t: number): unknown;
  stateAt(t: number): SceneState;
  bodyArraysAt(t: number, into?: BodyArrays): BodyArrays;
  nextEventTime(t: number): number | null;
  prevEventTime(t: number): number | null;
  event(i: number): LogEvent;
  eventDetail(i: number): EventDetail;
  eventIndexAt(t: number): number;
  eventsBetween(t0: number, t1: number): LogEvent[];
  path(id: string, from?: number, to?: number): PathPiece[];
  counts(): Counts;
  historyBytes(): number;
  toScene(): SceneFile;
}

/** Builds a timeline from a scene file; throws the engine's SceneError on invalid input. */
export type TimelineFactory = (scene: SceneFile) => TimelineLike;
