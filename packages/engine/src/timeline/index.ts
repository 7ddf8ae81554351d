/** Barrel of src/timeline: the public exports of this folder. */
export type { PathPiece } from "./path.js";
export { Timeline } from "./timeline.js";
export type {
  ApplyOptions,
  EventBody,
  EventDetail,
  LogEvent,
  LogKind,
  ProlongResult,
  SceneState,
  TimelineCounts,
  TimelineOptions,
} from "./types.js";
