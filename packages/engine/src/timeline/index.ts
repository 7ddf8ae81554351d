/** Barrel of src/timeline: the public exports of this folder. */
export type { PathPiece } from "./path.js";
export { Timeline } from "./timeline.js";
export type {
  ActionLogEvent,
  ApplyOptions,
  CollisionLogEvent,
  EventBody,
  EventDetail,
  LogEvent,
  LogKind,
  ProlongResult,
  SceneState,
  StopLogEvent,
  TimelineCounts,
  TimelineOptions,
} from "./types.js";
