import { describe, expect, it } from "vitest";
import { F_FROM, F_UNTIL, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { emptyFrame, frameAt } from "./frameAt";
import { MAX_GAP_SECONDS, TrailRecorder } from "./trails";

/** A frame of one body at (x, y) whose motion law (at rest here) holds over [from, until]. */
function frame(t: number, x: number, y: number, from = t, until = t): Frame {
  const data = new Float64Array(FRAME_STRIDE);
  data[F_X] = x;
  data[F_Y] = y;
  data[F_FROM] = from;
  data[F_UNTIL] = until;
  return { t, revision: 0, g: 0, gravity: [0, 0], ids: ["a"], data, lines: [], points: [] };
}

describe("TrailRecorder", () => {
  it("records positions of nearby times and clears on a jump", () => {
    const tr = new TrailRecorder();
    tr.record(frame(0, 0, 0));
    tr.record(frame(0.1, 1, 0));
    expect(tr.paths.get("a")).toEqual([0, 0, 1, 0]);
    tr.record(frame(0.1 + 2 * MAX_GAP_SECONDS, 5, 5));
    expect(tr.paths.get("a")).toEqual([5, 5]);
  });

  it("a scrub draws the old frame at the new time first (bodies waiting): no chord across the jump", () => {
    const tr = new TrailRecorder();
    const old = frame(0.3, 1, 1);
    tr.record(old);
    // the canvas shows the new time at once, the bodies held where the old frame knows them
    tr.record(frameAt(old, 6, emptyFrame()));
    // then the worker's frame of t = 6 arrives
    tr.record(frame(6, 7, 2));
    expect(tr.paths.get("a")).toEqual([7, 2]);
  });

  it("a body waiting for a newer frame gets no point until it moves again", () => {
    const tr = new TrailRecorder();
    const f = frame(0, 0, 0, 0, 0.05);
    tr.record(f);
    tr.record(frameAt(f, 0.1, emptyFrame()));
    expect(tr.paths.get("a")).toEqual([0, 0]);
  });
});
