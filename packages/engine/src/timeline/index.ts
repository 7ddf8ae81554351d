/** Barrel of src/timeline: the public exports of this folder. */
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
