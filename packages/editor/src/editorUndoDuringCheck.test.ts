// Undo pressed while an edit in the past is being checked (the host answers it only once the
// actions after it are checked: pendingEdit.ts). The Undo is the user's answer to that edit:
// it takes that edit back and nothing else, whether the check would have passed or refused it
// (it once undid the edit before as well when the checked edit was refused), and Redo brings back
// only what Undo took.
import { describe, expect, it } from "vitest";
import { canRedo } from "./doc/undoIntents";
import type { Action, SceneFile } from "./engineTypes";
import { settled } from "./testing/harness";
import { boxScene } from "./testing/scenes";
import { checking, count, slowEditorAt } from "./testing/sceneWatch";

const addE: Action = { time: 30, type: "addBody", id: "e", x: 50, y: 50, r: 1, m: 1 };
const box: SceneFile = boxScene([addE]);
/** The box with six discs near its floor (a to d, f, g): a check from t = 10 to 30 lasts a dozen events. */
const busyBox: SceneFile = boxScene(
  [addE],
  [..."abcdfg"].map((id, k): [string, number, number, [number, number]] => [
    id,
    5 + 7 * k,
    5,
    [6 - k, 2 + k],
  ]),
);
/** Refused once checked: e, added at t = 30, would overlap z. */
const blocker: Action = { time: 10, type: "addBody", id: "z", x: 50, y: 50.5, r: 1, m: 1 };
const earlier: Action = { time: 10, type: "giveVelocity", id: "b", v: [0, 1] };
const valid: Action = { time: 5, type: "giveVelocity", id: "a", v: [1, 1] };
/** Another change in the past (c's velocity at t = 7), checked up to e's addition at t = 30. */
const other: Action = { time: 7, type: "giveVelocity", id: "c", v: [-1, 0.5] };

/** The box with its history to t = 40 and one accepted edit (b's velocity at t = 10). */
async function boxWithOneEdit(scene = box) {
  const h = await slowEditorAt(scene, 40, 10);
  expect(await h.editor.edit([earlier])).toBeNull();
  await settled(h.client);
  return h;
}

describe("Undo while an edit's later actions are being checked", () => {
  it("takes back only that edit when the check would have refused it: the edit before stays", async () => {
    const h = await boxWithOneEdit();
    const seen = checking(h);
    const edit = h.editor.edit([blocker]);
    await seen;
    const undone = h.editor.undo();
    await edit;
    await undone;
    await settled(h.client);
    expect({ blocker: count(h, blocker), earlier: count(h, earlier) }).toEqual({ blocker: 0, earlier: 1 });
    expect(h.editor.history.getState().past).toHaveLength(1); // b's edit is still undoable
  });

  it("takes back only that edit when the check would have passed it, says so, and Redo brings it back once", async () => {
    const h = await boxWithOneEdit();
    h.editor.ui.setState({ t: 5 });
    const seen = checking(h);
    const edit = h.editor.edit([valid]);
    await seen;
    const undone = h.editor.undo();
    expect(await edit).not.toBeNull(); // not applied
    await undone;
    await settled(h.client);
    expect({ valid: count(h, valid), earlier: count(h, earlier) }).toEqual({ valid: 0, earlier: 1 });
    expect(h.editor.ui.getState().message).toEqual({
      text: 'Undone: give velocity to "a" at t = 5 s (taken back while the actions after it were being checked).',
      tone: "info",
    });
    await h.editor.redo();
    await settled(h.client);
    expect({ valid: count(h, valid), earlier: count(h, earlier) }).toEqual({ valid: 1, earlier: 1 });
    expect(h.editor.history.getState()).toMatchObject({ past: { length: 2 }, future: [] });
    await h.editor.undo();
    await h.editor.undo();
    await settled(h.client);
    expect({ valid: count(h, valid), earlier: count(h, earlier) }).toEqual({ valid: 0, earlier: 0 });
  });

  it("Undo then Redo during the check: the edit is there once, the edit before stays", async () => {
    const h = await boxWithOneEdit();
    h.editor.ui.setState({ t: 5 });
    const seen = checking(h);
    const edit = h.editor.edit([valid]);
    await seen;
    const undone = h.editor.undo();
    const redone = h.editor.redo();
    await Promise.all([edit, undone, redone]);
    await settled(h.client);
    expect({ valid: count(h, valid), earlier: count(h, earlier) }).toEqual({ valid: 1, earlier: 1 });
    expect(h.editor.history.getState()).toMatchObject({ past: { length: 2 }, future: [] });
  });

  it("Undo then Redo of a refused edit brings back nothing and undoes nothing", async () => {
    const h = await boxWithOneEdit();
    const seen = checking(h);
    const edit = h.editor.edit([blocker]);
    await seen;
    const undone = h.editor.undo();
    const redone = h.editor.redo();
    await Promise.all([edit, undone, redone]);
    await settled(h.client);
    expect({ blocker: count(h, blocker), earlier: count(h, earlier) }).toEqual({ blocker: 0, earlier: 1 });
    expect(h.editor.history.getState().past).toHaveLength(1);
  });

  it("an edit the check refuses leaves Redo as it was: off while the edit is shown and checked, the same entry after", async () => {
    // Redo is off during the check because the edit is made (shown, and Undo takes it back); a
    // refused edit was never made, so the entry comes back with nothing lost. Kept on through the
    // check, Redo would either redo the older entry over the edit shown or wait and then do
    // nothing once the edit passed.
    const h = await boxWithOneEdit();
    await h.editor.undo();
    await settled(h.client);
    const redoable = () => canRedo(h.editor.intents.getState(), h.editor.history.getState().future.length);
    expect(redoable()).toBe(true);
    const seen = checking(h);
    const edit = h.editor.edit([blocker]);
    await seen;
    expect({ blocker: count(h, blocker), redoable: redoable() }).toEqual({ blocker: 1, redoable: false });
    const redone = h.editor.redo(); // Ctrl+Shift+Z meanwhile: nothing to redo over the edit shown
    expect(await edit).not.toBeNull();
    await redone;
    await settled(h.client);
    expect({ blocker: count(h, blocker), earlier: count(h, earlier), redoable: redoable() }).toEqual({
      blocker: 0,
      earlier: 0,
      redoable: true,
    });
    await h.editor.redo();
    await settled(h.client);
    expect({ blocker: count(h, blocker), earlier: count(h, earlier) }).toEqual({ blocker: 0, earlier: 1 });
    expect(h.editor.history.getState()).toMatchObject({ past: { length: 1 }, future: [] });
  });

  it("Undo asked right after an edit (before the host has it) binds to that edit, not the one before", async () => {
    const h = await boxWithOneEdit();
    const edit = h.editor.edit([blocker]);
    const undone = h.editor.undo();
    await Promise.all([edit, undone]);
    await settled(h.client);
    expect({ blocker: count(h, blocker), earlier: count(h, earlier) }).toEqual({ blocker: 0, earlier: 1 });
  });

  it("two Undos during the check take back that edit and the one before, no more", async () => {
    const h = await boxWithOneEdit();
    h.editor.ui.setState({ t: 5 });
    const seen = checking(h);
    const edit = h.editor.edit([valid]);
    await seen;
    await Promise.all([edit, h.editor.undo(), h.editor.undo(), h.editor.undo()]);
    await settled(h.client);
    expect({ valid: count(h, valid), earlier: count(h, earlier) }).toEqual({ valid: 0, earlier: 0 });
    expect(h.editor.history.getState()).toMatchObject({ past: [], future: { length: 2 } });
    await h.editor.redo();
    await h.editor.redo();
    await settled(h.client);
    expect({ valid: count(h, valid), earlier: count(h, earlier) }).toEqual({ valid: 1, earlier: 1 });
  });

  it("Redo of an edit Undo took back during its check checks it again: refused, it leaves Redo and nothing else moves", async () => {
    const h = await boxWithOneEdit(busyBox);
    const seen = checking(h);
    const edit = h.editor.edit([blocker]);
    await seen;
    await Promise.all([edit, h.editor.undo()]);
    expect(h.editor.ui.getState().message?.text).toMatch(/^Undone: add body "z" at t = 10 s \(taken back/);
    expect(h.editor.history.getState().future).toHaveLength(1);
    await h.editor.redo();
    await settled(h.client);
    expect(h.editor.ui.getState().message).toMatchObject({
      tone: "error",
      text: expect.stringMatching(/overlap/),
    });
    expect({ blocker: count(h, blocker), earlier: count(h, earlier) }).toEqual({ blocker: 0, earlier: 1 });
    expect(h.editor.history.getState()).toMatchObject({ past: { length: 1 }, future: [] });
  });

  it("Undo during the check of a removal from the Event log puts the action back, and says which", async () => {
    const h = await boxWithOneEdit();
    const i = h.client.getSnapshot().doc!.actions.findIndex((a) => a.type === "giveVelocity");
    const seen = checking(h);
    const removed = h.editor.removeAction(i, { time: 10, type: "giveVelocity", id: "b" });
    await seen;
    await Promise.all([removed, h.editor.undo()]);
    await settled(h.client);
    expect(count(h, earlier)).toBe(1);
    expect(h.editor.ui.getState().message?.text).toBe(
      'Undone: the removal of give velocity to "b" at t = 10 s (taken back while the actions after it were being checked).',
    );
  });

  it("a new edit clears Redo even when Undo takes it back during its check: Redo then brings back only that edit", async () => {
    // The audit's sequence: X undone (X in Redo), Y asked and taken back by Undo during its check,
    // Redo brings Y back; Redo once more used to load X's stored scene (X back, Y silently gone).
    const h = await boxWithOneEdit();
    expect(await h.editor.edit([valid])).toBeNull(); // X
    await settled(h.client);
    await h.editor.undo();
    await settled(h.client);
    expect(h.editor.history.getState().future).toHaveLength(1); // X in Redo
    const seen = checking(h);
    const edit = h.editor.edit([other]); // Y
    await seen;
    await Promise.all([edit, h.editor.undo()]);
    await settled(h.client);
    expect(h.editor.history.getState()).toMatchObject({ past: { length: 1 }, future: { length: 1 } });
    await h.editor.redo();
    await settled(h.client);
    const state = () => ({
      valid: count(h, valid),
      other: count(h, other),
      earlier: count(h, earlier),
      past: h.editor.history.getState().past.length,
      future: h.editor.history.getState().future.length,
      canRedo: canRedo(h.editor.intents.getState(), h.editor.history.getState().future.length),
    });
    expect(state()).toEqual({ valid: 0, other: 1, earlier: 1, past: 2, future: 0, canRedo: false });
    await h.editor.redo(); // nothing to redo
    await settled(h.client);
    expect(state()).toEqual({ valid: 0, other: 1, earlier: 1, past: 2, future: 0, canRedo: false });
  });
});
