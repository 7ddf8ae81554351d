/**
 * The engine contract types the editor uses (docs/architecture.md), in one place so the rest of the
 * editor imports them from here. Temporary local copy until @chapgame/engine exports them.
 */
export type Vec2 = readonly [number, number];
export type LineKind = "line" | "ray" | "segment";
export type EventKind = "bodyBody" | "bodyLine" | "bodyPoint" | "stop";
export interface Until {
  time?: number;
  events?: number;
}
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
export interface LogEvent {
  time: number;
  type: EventKind | "action";
  ids: string[];
  point: Vec2 | null;
  normal: Vec2 | null;
  impulse: number | null;
}
export interface BodyState {
  id: string;
  x: number;
  y: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
  r: number;
  m: number;
  mu: number;
}
export interface LineState {
  id: string;
  p1: Vec2;
  p2: Vec2;
  kind: LineKind;
}
export interface PointState {
  id: string;
  p: Vec2;
}
export interface SceneState {
  time: number;
  g: number;
  gravity: Vec2;
  bodies: BodyState[];
  lines: LineState[];
  points: PointState[];
}
export interface SceneFile {
  format: "chapgame";
  version: 1;
  g: number;
  gravity: Vec2;
  actions: Action[];
}
export interface Counts {
  bodyBody: number;
  bodyLine: number;
  bodyPoint: number;
  stop: number;
  action: number;
}
