/**
 * Counters of the canvas loop for in-browser measurements (tests/e2e/*.measure.ts): frames drawn,
 * time spent drawing, and frame round trips to the worker. Read through `window.chapgameStats`.
 */
export interface DrawStats {
  /** canvas redraws */
  draws: number;
  /** milliseconds spent in drawFrame, summed */
  drawMs: number;
  /** frames received from the worker */
  frames: number;
  /** milliseconds from asking a frame to receiving it, summed */
  frameLatencyMs: number;
  /** the largest single frame latency seen */
  maxFrameLatencyMs: number;
  /** bodies drawn waiting at the end of their motion-law interval (frameAt), summed over draws */
  heldBodies: number;
  /** bodies drawn, summed over draws */
  drawnBodies: number;
}

export const drawStats: DrawStats = {
  draws: 0,
  drawMs: 0,
  frames: 0,
  frameLatencyMs: 0,
  maxFrameLatencyMs: 0,
  heldBodies: 0,
  drawnBodies: 0,
};

export function resetDrawStats(): void {
  drawStats.draws = 0;
  drawStats.drawMs = 0;
  drawStats.frames = 0;
  drawStats.frameLatencyMs = 0;
  drawStats.maxFrameLatencyMs = 0;
  drawStats.heldBodies = 0;
  drawStats.drawnBodies = 0;
}
