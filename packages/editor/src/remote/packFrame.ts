/** Packs a SceneState into a Frame (protocol.ts): bodies as FRAME_STRIDE numbers each. */
import type { SceneState } from "../engineTypes";
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
