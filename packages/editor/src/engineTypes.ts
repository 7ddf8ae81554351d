/**
 * The engine contract types the editor uses (docs/architecture.md), re-exported in one place so the
 * rest of the editor imports them from here.
 */
export type {
  Action,
  BodyArrays,
  BodyState,
  EventBody,
  EventDetail,
  EventKind,
  LineKind,
  LineState,
  LogEvent,
  PathPiece,
  PointState,
  SceneFile,
  SceneState,
  TimelineCounts as Counts,
  Until,
  Vec2,
} from "@chapgame/engine";
