/**
 * Packs a SceneState, or bodies read as arrays (BodyArrays) with the rest of a frame, into a Frame
 * (protocol.ts): bodies as FRAME_STRIDE numbers each, the same numbers either way.
 */
import type { BodyArrays, SceneState } from "../engineTypes";
import {
  F_AX,
  F_AY,
  F_FROM,
  F_M,
  F_MU,
  F_R,
  F_UNTIL,
  F_VX,
  F_VY,
  F_X,
  F_Y,
  FRAME_STRIDE,
  type Frame,
} from "./protocol";

/**
 * `previousIds`: the ids of the last frame sent; when unchanged, the frame carries the same array
 * (the host then sends `ids: null` and the client reuses its copy, saving thousands of strings per
 * frame). Motion-law intervals are empty ([t, t]); markValidity (validity.ts) widens them.
 */
export function packFrame(s: SceneState, revision: number, previousIds: string[] | null = null): Frame {
  const n = s.bodies.length;
  const data = new Float64Array(n * FRAME_STRIDE);
  let ids: string[] = new Array(n);
  let same = previousIds !== null && previousIds.length === n;
  for (let i = 0; i < n; i++) {
    const b = s.bodies[i]!;
    const o = i * FRAME_STRIDE;
    ids[i] = b.id;
    if (same && previousIds![i] !== b.id) same = false;
    data[o + F_X] = b.x;
    data[o + F_Y] = b.y;
    data[o + F_VX] = b.vx;
    data[o + F_VY] = b.vy;
    data[o + F_AX] = b.ax;
    data[o + F_AY] = b.ay;
    data[o + F_R] = b.r;
    data[o + F_M] = b.m;
    data[o + F_MU] = b.mu;
    data[o + F_FROM] = s.time;
    data[o + F_UNTIL] = s.time;
  }
  if (same) ids = previousIds!;
  return { t: s.time, revision, g: s.g, gravity: s.gravity, ids, data, lines: s.lines, points: s.points };
}

/** What a frame holds besides its bodies: the scene's fields and obstacles at the frame's time. */
export type FrameStatics = Pick<SceneState, "g" | "gravity" | "lines" | "points">;

/**
 * The frame of `a` (bodyArraysAt) and `statics` (the same time's), with `ids` as the frame's ids
 * (the caller's, holding a.ids: packFrame's reuse of the previous frame's array is FrameReader's).
 * The same frame as packFrame(stateAt(a.time)) gives. Motion-law intervals are empty ([t, t]).
 */
export function packArrays(a: BodyArrays, statics: FrameStatics, revision: number, ids: string[]): Frame {
  const n = a.count;
  const data = new Float64Array(n * FRAME_STRIDE);
  const { x, y, vx, vy, ax, ay, r, m, mu } = a;
  const t = a.time;
  for (let i = 0; i < n; i++) {
    const o = i * FRAME_STRIDE;
    data[o + F_X] = x[i]!;
    data[o + F_Y] = y[i]!;
    data[o + F_VX] = vx[i]!;
    data[o + F_VY] = vy[i]!;
    data[o + F_AX] = ax[i]!;
    data[o + F_AY] = ay[i]!;
    data[o + F_R] = r[i]!;
    data[o + F_M] = m[i]!;
    data[o + F_MU] = mu[i]!;
    data[o + F_FROM] = t;
    data[o + F_UNTIL] = t;
  }
  const { g, gravity, lines, points } = statics;
  return { t, revision, g, gravity, ids, data, lines, points };
}
