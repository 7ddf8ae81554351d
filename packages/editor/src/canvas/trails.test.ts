import { billiardsBreak } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { Editor } from "../editor";
import { LOOKAHEAD_SECONDS } from "../playback";
import { F_FROM, F_UNTIL, F_VX, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { settled, testEditor } from "../testing/harness";
import { emptyFrame, frameAt } from "./frameAt";
import { bodyActions, MAX_GAP_SECONDS, TrailRecorder } from "./trails";

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

/** A frame of one body "a" from explicit fields: place, velocity and the interval of its law. */
function law(t: number, x: number, vx: number, from: number, until: number): Frame {
  const f = frame(t, x, 0, from, until);
  f.data[F_VX] = vx;
  return f;
}

describe("TrailRecorder across an action that moves a body", () => {
  it("an edit of the place at the time shown starts the trail again (it drew a line from the old place)", () => {
    const tr = new TrailRecorder();
    tr.record(law(1.9, 0.9, 1, 0, 10));
    tr.record(law(2, 1, 1, 0, 10));
    // the edit at t = 2: the frame of the new revision, the body elsewhere from t = 2 on
    tr.record(law(2, 5, 1, 2, 10));
    expect(tr.paths.get("a")).toEqual([5, 0]);
    tr.record(law(2.1, 5.1, 1, 2, 10));
    expect(tr.paths.get("a")).toEqual([5, 0, 5.1, 0]);
  });

  it("scrubbing paused over an action (frames without intervals) starts the trail again there", () => {
    const tr = new TrailRecorder();
    const actionAt2 = bodyActions([{ time: 2, type: "updateBody", id: "a", x: 5 }]);
    tr.record(law(1.9, 0.9, 1, 1.9, 1.9), actionAt2);
    tr.record(law(1.95, 0.95, 1, 1.95, 1.95), actionAt2);
    expect(tr.paths.get("a")).toEqual([0.9, 0, 0.95, 0]);
    tr.record(law(2.1, 5.1, 1, 2.1, 2.1), actionAt2);
    expect(tr.paths.get("a")).toEqual([5.1, 0]);
  });

  it("playing over the action, forwards and backwards, starts the trail again there", () => {
    const tr = new TrailRecorder();
    tr.record(law(1.9, 0.9, 1, 0, 2));
    tr.record(law(2.1, 5.1, 1, 2, 10));
    expect(tr.paths.get("a")).toEqual([5.1, 0]);
    tr.record(law(2.2, 5.2, 1, 2, 10));
    tr.record(law(1.95, 0.95, 1, 0, 2));
    expect(tr.paths.get("a")).toEqual([0.95, 0]);
  });

  it("a collision (the velocity changes, not the place) keeps the trail", () => {
    const tr = new TrailRecorder();
    tr.record(law(1.9, 0.9, 1, 0, 2));
    // at t = 2 the body at x = 1 turns back
    tr.record(law(2.1, 0.9, -1, 2, 10));
    tr.record(law(1.95, 0.95, 1, 0, 2));
    expect(tr.paths.get("a")).toEqual([0.9, 0, 0.9, 0, 0.95, 0]);
  });
});

describe("TrailRecorder on the engine's frames", () => {
  /** Records the frames at `times`; returns the ids whose trail started again on the way. */
  async function restarts(editor: Editor, times: number[], window: number): Promise<string[]> {
    const { client } = editor;
    const acted = bodyActions(editor.doc.actions);
    const tr = new TrailRecorder();
    const out: string[] = [];
    for (const t of times) {
      const before = new Map([...tr.paths].map(([id, p]) => [id, p.length]));
      tr.record(await client.frame(t, window), acted);
      for (const [id, p] of tr.paths) if ((before.get(id) ?? 0) > 0 && p.length === 2) out.push(id);
    }
    return out;
  }
  const steps = (from: number, to: number) =>
    Array.from(
      { length: Math.round(Math.abs(to - from) * 60) + 1 },
      (_, i) => from + (Math.sign(to - from) * i) / 60,
    );

  it("a break's collisions, cushions and stops keep every trail; a disc moved by an action starts its own again", async () => {
    const { editor, client } = testEditor();
    expect(await editor.loadScene(billiardsBreak(), { undoable: false })).toBeNull();
    await editor.goTo(4);
    await settled(client);
    // paused (frames without motion-law intervals) and playing (intervals of a quarter second)
    for (const window of [0, LOOKAHEAD_SECONDS]) {
      expect(await restarts(editor, steps(0, 3), window)).toEqual([]);
      expect(await restarts(editor, steps(3, 0), window)).toEqual([]);
    }
    editor.setTime(1.5);
    const cue = await client.frame(1.5);
    const i = cue.ids.indexOf("cue") * FRAME_STRIDE;
    expect(await editor.moveBody("cue", cue.data[i + F_X]!, cue.data[i + F_Y]! + 30)).toBeNull();
    await settled(client);
    for (const window of [0, LOOKAHEAD_SECONDS]) {
      expect(await restarts(editor, steps(1, 2), window)).toEqual(["cue"]);
      expect(await restarts(editor, steps(2, 1), window)).toEqual(["cue"]);
    }
  });
});
