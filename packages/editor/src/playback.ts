/**
 * The playback clock: on every animation frame while playing, time moves by speed × elapsed
 * wall-clock time (negative speeds replay backwards), clamped to [0, horizon]. Playing forward near
 * the horizon asks for more computation (auto-extend) and waits at the horizon for it; playback
 * pauses at 0 going backwards and at the horizon when nothing more can be computed. A time past the
 * horizon (the history being recomputed after an undo) is held until the computation reaches it.
 */
import type { Editor } from "./editor";

/** Longest wall-clock step taken in one frame (s): a stalled tab does not jump ahead. */
export const MAX_FRAME_SECONDS = 0.1;
/** Auto-extend starts when the horizon is less than this many seconds of playback away. */
export const EXTEND_LEAD_SECONDS = 2;

/**
 * Wall-clock seconds of playback that one frame from the worker should cover: frames asked while
 * playing carry motion-law intervals reaching |speed| × this many seconds around their time, so the
 * canvas draws the exact time of each animation frame (canvas/frameAt.ts) even when the worker's
 * answer takes several frames.
 */
export const LOOKAHEAD_SECONDS = 0.25;

/** The motion-law window (simulation seconds) to ask frames with: 0 while paused. */
export function motionWindow(s: { playing: boolean; speed: number }): number {
  return s.playing ? Math.abs(s.speed) * LOOKAHEAD_SECONDS : 0;
}

/**
 * Whether playing forward may ask for more computation: auto-extend is on, events are left, and the
 * engine did not refuse to go on (a computation stopped by a Zeno state would stop again at once).
 */
export function canExtend(autoExtend: boolean, info: { idle: boolean; stopped: string | null }): boolean {
  return autoExtend && !info.idle && info.stopped === null;
}

/** Pure step of the clock. Returns the new time and whether playback must stop. */
export function advanceClock(
  t: number,
  speed: number,
  dt: number,
  horizon: number,
  canExtend: boolean,
): { t: number; stop: boolean } {
  // Ahead of the computed history (an undo or a rename recomputes it from the start while the time
  // stays): wait there while it is computed, rather than jump back to where it has got so far.
  // Nothing coming: back to the end of the history, from where a backward play goes on.
  if (t > horizon) return canExtend ? { t, stop: false } : { t: horizon, stop: speed > 0 };
  const next = t + speed * Math.min(dt, MAX_FRAME_SECONDS);
  if (next <= 0 && speed < 0) return { t: 0, stop: true };
  if (next >= horizon && speed > 0) return { t: horizon, stop: !canExtend };
  return { t: Math.min(Math.max(next, 0), horizon), stop: false };
}

export function startPlayback(editor: Editor, now: () => number = () => performance.now()): () => void {
  const { ui, client } = editor;
  let last = now();
  let askedAtRevision = -1;
  let raf = requestAnimationFrame(function frame() {
    raf = requestAnimationFrame(frame);
    const time = now();
    const dt = (time - last) / 1000;
    last = time;
    const s = ui.getState();
    const info = client.getSnapshot();
    const extend = canExtend(s.calc.autoExtend, info);
    if (s.playing && s.speed > 0 && extend && !info.computing && info.revision !== askedAtRevision) {
      const lead = Math.max(EXTEND_LEAD_SECONDS, 2 * s.speed);
      if (info.horizon - s.t < lead) {
        askedAtRevision = info.revision;
        editor.computeAhead();
      }
    }
    if (!s.playing || s.speed === 0) return;
    // Auto-extend asks for more only when playing forwards: backwards, only a running computation
    // is worth waiting for (an undo's, past whose horizon the time may stand).
    const waiting = info.computing !== null || (s.speed > 0 && extend);
    const step = advanceClock(s.t, s.speed, dt, info.horizon, waiting);
    ui.setState(step.stop ? { t: step.t, playing: false } : { t: step.t });
  });
  return () => cancelAnimationFrame(raf);
}
