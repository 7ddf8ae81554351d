/**
 * A frame's bodies at another time, evaluated on the main thread from the motion laws the frame
 * carries (protocol.ts): p(t) = p + v·dt + a·dt²/2 and v(t) = v + a·dt with dt = t − frame time,
 * each body's t clamped to its interval [F_FROM, F_UNTIL]. Inside the interval this is the body's
 * exact motion (rounding apart); a body whose interval ends before t (an event the frame does not
 * know the outcome of) waits at its interval's end until a newer frame arrives.
 */
import {
  F_AX,
  F_AY,
  F_FROM,
  F_UNTIL,
  F_VX,
  F_VY,
  F_X,
  F_Y,
  FRAME_STRIDE,
  type Frame,
} from "../remote/protocol";

/**
 * Evaluates `base` at time t into `out` (its data buffer is reused when the size fits); returns out.
 * `held`, when given, counts the bodies waiting at the end of their interval (t outside it).
 */
export function frameAt(base: Frame, t: number, out: Frame, held?: { count: number }): Frame {
  const src = base.data;
  if (out.data.length !== src.length) out.data = new Float64Array(src.length);
  const d = out.data;
  d.set(src);
  const n = src.length / FRAME_STRIDE;
  for (let i = 0; i < n; i++) {
    const o = i * FRAME_STRIDE;
    const tt = Math.min(Math.max(t, src[o + F_FROM]!), src[o + F_UNTIL]!);
    if (held && tt !== t) held.count++;
    const dt = tt - base.t;
    if (dt === 0) continue;
    const vx = src[o + F_VX]!;
    const vy = src[o + F_VY]!;
    const ax = src[o + F_AX]!;
    const ay = src[o + F_AY]!;
    d[o + F_X] = src[o + F_X]! + dt * (vx + 0.5 * ax * dt);
    d[o + F_Y] = src[o + F_Y]! + dt * (vy + 0.5 * ay * dt);
    d[o + F_VX] = vx + ax * dt;
    d[o + F_VY] = vy + ay * dt;
  }
  out.t = t;
  out.revision = base.revision;
  out.g = base.g;
  out.gravity = base.gravity;
  out.ids = base.ids;
  out.lines = base.lines;
  out.points = base.points;
  return out;
}

/** An empty frame to evaluate into. */
export function emptyFrame(): Frame {
  return {
    t: 0,
    revision: -1,
    g: 0,
    gravity: [0, 0],
    ids: [],
    data: new Float64Array(0),
    lines: [],
    points: [],
  };
}
