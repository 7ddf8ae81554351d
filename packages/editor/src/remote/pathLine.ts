/**
 * A body's whole computed path as a polyline to draw (the canvas's Path view; worker op `path`).
 * Pure. From the engine's exact pieces (Timeline.path): a straight piece (no acceleration, or at rest)
 * gives its two ends; a curved one (friction slowing it, gravity bending it) CURVE_SEGMENTS + 1 points
 * evenly spaced in time up to where it stops. Each point is the piece's exact position at its time
 * (positionAt, as the engine evaluates it). Where the next piece does not start where the last one
 * ended (an action moved the body, or removed it and added it again), the line breaks: a NaN pair.
 * The line holds at most `maxPoints` points: a longer path is cut at the end of the last whole piece
 * that fits, and `cutAt` says at what time (null when whole), so the view can say so.
 */
import { positionAt } from "@chapgame/engine";
import type { PathPiece } from "../engineTypes";

/** Segments per curved piece: a parabola or a braking line drawn within a pixel at the usual zooms. */
export const CURVE_SEGMENTS = 24;
/** Default cap of a drawn path's points (a body of a long gas history has tens of thousands of pieces). */
export const PATH_MAX_POINTS = 100_000;

export interface PathLine {
  /** x0, y0, x1, y1, ...; a NaN pair breaks the line. */
  points: Float64Array;
  /** The time the line was cut at (it holds the path up to there), or null when it holds all of it. */
  cutAt: number | null;
}

const x = (p: PathPiece, t: number) => positionAt(p.t0, p.x0, p.vx, p.ax, Math.min(t, p.tStop));
const y = (p: PathPiece, t: number) => positionAt(p.t0, p.y0, p.vy, p.ay, Math.min(t, p.tStop));

/** The times a piece is drawn at (see the header). */
function sampleTimes(p: PathPiece): number[] {
  const end = Math.min(p.until, Math.max(p.tStop, p.from));
  if ((p.ax === 0 && p.ay === 0) || end <= p.from) return [p.from, p.until];
  const times = Array.from(
    { length: CURVE_SEGMENTS + 1 },
    (_, k) => p.from + ((end - p.from) * k) / CURVE_SEGMENTS,
  );
  times[CURVE_SEGMENTS] = end;
  return times;
}

export function pathLine(pieces: readonly PathPiece[], maxPoints = PATH_MAX_POINTS): PathLine {
  const out: number[] = [];
  let points = 0;
  let lastX = Number.NaN;
  let lastY = Number.NaN;
  for (const p of pieces) {
    const times = sampleTimes(p);
    const sx = x(p, p.from);
    const sy = y(p, p.from);
    const joined = sx === lastX && sy === lastY;
    const need = times.length - (joined ? 1 : 0) + (joined || points === 0 ? 0 : 1);
    if (points + need > maxPoints) return { points: Float64Array.from(out), cutAt: p.from };
    if (!joined && points > 0) {
      out.push(Number.NaN, Number.NaN);
      points++;
    }
    for (let k = joined ? 1 : 0; k < times.length; k++) {
      const t = times[k] as number;
      out.push(x(p, t), y(p, t));
      points++;
    }
    lastX = out[out.length - 2] as number;
    lastY = out[out.length - 1] as number;
  }
  return { points: Float64Array.from(out), cutAt: null };
}
