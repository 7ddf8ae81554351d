// Undo and Redo around more than one change in flight, and Cancel or a restart during a Redo's
// check (review of session 16). Two edits in the past asked one after the other: the first is being
// checked, the second queued behind it. Two Undos are bound to them, the last first; taking the
// first back at once (it was running) made the second run on a scene without it, and the second
// Redo then loaded "base + second edit", silently removing the first. A Redo of an edit an Undo
// took back during its check checks it again: Cancel or an engine restart during that check used to
// drop the edit from Redo (only a refusal naming a later action should).
import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "./engineTypes";
import { settled, type testEditor } from "./testing/harness";
import { boxScene } from "./testing/scenes";
import { checking, count, slowEditorAt } from "./testing/sceneWatch";

const addE: Action = { time: 30, type: "addBody", id: "e", x: 50, y: 50, r: 1, m: 1 };
const box: SceneFile = boxScene([addE]);
const first: Action = { time: 5, type: "giveVelocity", id: "a", v: [1, 1] };
const secondAt = (time: number): Action => ({ time, type: "giveVelocity", id: "c", v: [-1, 0.5] });

type Harness = ReturnType<typeof testEditor>;

/** The box with its history to t = 40, at t = 5. */
function boxAt5(): Promise<Harness> {
  return slowEditorAt(box, 40, 5);
}

describe("two edits in flight, two Undos, two Redos", () => {
  for (const t of [0, 7]) {
    it(`the second at t = ${t}: the scene goes back to the base, Redo brings the first, then both`, async () => {
      const h = await boxAt5();
      const second = secondAt(t);
      const state = () => ({ first: count(h, first), second: count(h, second) });
      const seen = checking(h);
      const e1 = h.editor.edit([first]);
      await seen; // the first edit's check runs
      const e2 = h.editor.edit([second]); // queued behind it
      const u2 = h.editor.undo(); // bound to the second
      const u1 = h.editor.undo(); // bound to the first (running)
      await Promise.all([e1, e2, u2, u1]);
      await settled(h.client);
      expect(state()).toEqual({ first: 0, second: 0 });
      expect(h.editor.ui.getState().message?.text).toMatch(/^Undone: give velocity to "a" at t = 5 s/);
      expect(h.editor.history.getState()).toMatchObject({ past: [], future: { length: 2 } });
      await h.editor.redo();
      await settled(h.client);
      expect(state()).toEqual({ first: 1, second: 0 });
      await h.editor.redo();
      await settled(h.client);
      expect(state()).toEqual({ first: 1, second: 1 });
      expect(h.editor.ui.getState().message?.text).toBe(`Redone: give velocity to "c" at t = ${t} s.`);
      expect(h.editor.history.getState()).toMatchObject({ past: { length: 2 }, future: [] });
    });
  }

  it("one Undo bound to the second (queued) edit undoes only that one", async () => {
    const h = await boxAt5();
    const second = secondAt(7);
    const seen = checking(h);
    const e1 = h.editor.edit([first]);
    await seen;
    const e2 = h.editor.edit([second]);
    const [r1] = await Promise.all([e1, e2, h.editor.undo()]);
    await settled(h.client);
    expect(r1).toBeNull(); // the first edit was not taken back
    expect({ first: count(h, first), second: count(h, second) }).toEqual({ first: 1, second: 0 });
    await h.editor.redo();
    await settled(h.client);
    expect({ first: count(h, first), second: count(h, second) }).toEqual({ first: 1, second: 1 });
  });
});

/** An edit taken back by an Undo during its check (alone in Redo, unchecked), then Redo asked; resolves during its check. */
async function redoChecking(h: Harness): Promise<{ redone: Promise<void> }> {
  let seen = checking(h);
  const e1 = h.editor.edit([first]);
  await seen;
  await Promise.all([e1, h.editor.undo()]);
  await settled(h.client);
  expect(h.editor.history.getState().future).toHaveLength(1);
  seen = checking(h);
  const redone = h.editor.redo();
  await seen;
  return { redone }; // not awaited: an async function's value would wait for it
}

describe("a Redo's check of an edit taken back during its check", () => {
  it("cancelled, the edit stays in Redo and a later Redo brings it back", async () => {
    const h = await boxAt5();
    const { redone } = await redoChecking(h);
    h.editor.cancelCompute();
    await redone;
    await settled(h.client);
    expect(h.editor.ui.getState().message?.text).toMatch(/^Cancelled: the change was taken back/);
    expect(count(h, first)).toBe(0);
    expect(h.editor.history.getState().future).toHaveLength(1);
    await h.editor.redo();
    await settled(h.client);
    expect(count(h, first)).toBe(1);
    expect(h.editor.history.getState()).toMatchObject({ past: { length: 1 }, future: [] });
  });

  it("cut short by an engine restart, the edit stays in Redo", async () => {
    const h = await boxAt5();
    const { redone } = await redoChecking(h);
    await h.editor.restartEngine();
    await redone;
    await settled(h.client);
    expect(count(h, first)).toBe(0);
    expect(h.editor.history.getState().future).toHaveLength(1);
    await h.editor.redo();
    await settled(h.client);
    expect(count(h, first)).toBe(1);
  });
});
