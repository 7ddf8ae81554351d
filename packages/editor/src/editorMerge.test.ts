// Consecutive edits of one object at one instant are one action of the scene (doc/mergeEdit.ts),
// while Undo still takes back one edit at a time; the history is the one the merged action gives
// built from scratch, a refusal changes nothing, and a later action refusing a merged edit is named
// by its index in the scene the user has.
import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "./engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE } from "./remote/protocol";
import { settled, testEditor } from "./testing/harness";
import { boxScene } from "./testing/scenes";
import { checking, slowEditorAt } from "./testing/sceneWatch";

const addA: Action = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
const addB: Action = { time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1, v: [-1, 0] };
const scene = (...later: Action[]): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [addA, addB, ...later],
});

async function open(doc: SceneFile, t: number) {
  const h = testEditor();
  expect(await h.editor.loadScene(doc, { undoable: false })).toBeNull();
  await settled(h.client);
  h.editor.ui.setState({ t });
  return h;
}

/** Body `id` at time t in the editor's history: x, y, r. */
async function bodyAt(h: Awaited<ReturnType<typeof open>>, id: string, t: number) {
  const f = await h.client.frame(t);
  const i = f.ids.indexOf(id) * FRAME_STRIDE;
  return [f.data[i + F_X], f.data[i + F_Y], f.data[i + F_R]];
}

describe("edits of one object at one instant", () => {
  it("x, then y, then r of a body at t = 2 are one action; Undo takes them back one at a time", async () => {
    const h = await open(scene(), 2);
    const { editor, client } = h;
    expect(await editor.updateBody("a", { x: 3 })).toBeNull();
    expect(await editor.updateBody("a", { y: 4 })).toBeNull();
    expect(await editor.updateBody("a", { r: 0.5 })).toBeNull();
    await settled(client);
    expect(editor.doc.actions.slice(2)).toEqual([
      { time: 2, type: "updateBody", id: "a", x: 3, y: 4, r: 0.5 },
    ]);
    expect(await bodyAt(h, "a", 2)).toEqual([3, 4, 0.5]);
    expect(editor.history.getState().past).toHaveLength(3);
    // the Event log has one action entry at t = 2
    const page = await client.events(2, 50, 50, null);
    const actions = page.events.filter((e) => e.type === "action");
    expect(actions.map((e) => e.time)).toEqual([0, 0, 2]);

    await editor.undo();
    await settled(client);
    expect(editor.ui.getState().message?.text).toBe('Undone: the change of r in update body "a" at t = 2 s.');
    expect(editor.doc.actions.at(-1)).toEqual({ time: 2, type: "updateBody", id: "a", x: 3, y: 4 });
    await editor.undo();
    await settled(client);
    expect(editor.doc.actions.at(-1)).toEqual({ time: 2, type: "updateBody", id: "a", x: 3 });
    await editor.undo();
    await settled(client);
    expect(editor.doc.actions).toHaveLength(2);
    await editor.redo();
    await editor.redo();
    await settled(client);
    expect(editor.ui.getState().message?.text).toBe('Redone: the change of y in update body "a" at t = 2 s.');
    expect(editor.doc.actions.at(-1)).toEqual({ time: 2, type: "updateBody", id: "a", x: 3, y: 4 });
  });

  it("the history is the merged action's, as built from scratch, later actions kept", async () => {
    const kick: Action = { time: 5, type: "giveVelocity", id: "a", v: [0, 2] };
    const h = await open(scene(kick), 1);
    expect(await h.editor.updateBody("a", { y: 1 })).toBeNull();
    expect(await h.editor.giveVelocity("a", [2, 0])).toBeNull();
    expect(await h.editor.updateBody("a", { x: -3 })).toBeNull();
    await settled(h.client);
    const merged: Action = { time: 1, type: "updateBody", id: "a", y: 1, v: [2, 0], x: -3 };
    expect(h.editor.doc.actions.slice(2)).toEqual([merged, kick]);
    const fresh = await open(scene(merged, kick), 1);
    for (const t of [1, 2.5, 4, 5, 7.25])
      for (const id of ["a", "b"]) expect(await bodyAt(h, id, t)).toEqual(await bodyAt(fresh, id, t));
    expect(await h.client.nextEvent(1)).toBe(await fresh.client.nextEvent(1));
  });

  it("an edit that puts back what the edit before it changed leaves no action: the scene, its file and its log as before both; Undo steps back", async () => {
    const h = await open(scene(), 2);
    const { editor, client } = h;
    const before = editor.doc;
    const motion = await bodyAt(h, "b", 6);
    expect(await editor.updateBody("b", { m: 2 })).toBeNull();
    expect(await editor.updateBody("b", { m: 1 })).toBeNull(); // b's mass at t = 2 again
    await settled(client);
    expect(editor.doc.actions).toEqual(before.actions);
    const page = await client.events(2, 50, 50, null);
    expect(page.events.filter((e) => e.type === "action").map((e) => e.time)).toEqual([0, 0]);
    expect(await bodyAt(h, "b", 6)).toEqual(motion);
    expect(editor.history.getState().past).toHaveLength(2);
    await editor.undo();
    await settled(client);
    expect(editor.doc.actions.slice(2)).toEqual([{ time: 2, type: "updateBody", id: "b", m: 2 }]);
    await editor.undo();
    await settled(client);
    expect(editor.doc.actions).toEqual(before.actions);
    // at the instant a disc was added, its add stays (an add always changes something)
    editor.ui.setState({ t: 0 });
    expect(await editor.updateBody("b", { m: 2 })).toBeNull();
    expect(await editor.updateBody("b", { m: 1 })).toBeNull();
    await settled(client);
    expect(editor.doc.actions).toEqual(before.actions); // b's add, with m = 1
    expect(editor.history.getState().past).toHaveLength(2);
  });

  it("stays separate with another object's edit between, or at another time", async () => {
    const { editor, client } = await open(scene(), 2);
    expect(await editor.updateBody("a", { x: -3 })).toBeNull();
    expect(await editor.updateBody("b", { y: 5 })).toBeNull();
    expect(await editor.updateBody("a", { y: -2 })).toBeNull();
    editor.ui.setState({ t: 3 });
    expect(await editor.updateBody("a", { r: 0.5 })).toBeNull();
    await settled(client);
    expect(editor.doc.actions.slice(2)).toEqual([
      { time: 2, type: "updateBody", id: "a", x: -3 },
      { time: 2, type: "updateBody", id: "b", y: 5 },
      { time: 2, type: "updateBody", id: "a", y: -2 },
      { time: 3, type: "updateBody", id: "a", r: 0.5 },
    ]);
  });

  it("a merged edit the engine refuses changes nothing, the action before it kept as it was", async () => {
    const { editor, client } = await open(scene(), 2);
    expect(await editor.updateBody("a", { x: 3 })).toBeNull();
    await settled(client);
    const before = editor.doc;
    // b is at x = 8 at t = 2: a radius of 5 at x = 3 overlaps it
    expect(await editor.updateBody("a", { r: 5 })).toMatch(/^body "a" would overlap body "b"/);
    await settled(client);
    expect(editor.doc).toEqual(before);
    expect(editor.history.getState().past).toHaveLength(1);
  });

  it("a later action the merged edit makes invalid is named by its index in the scene the user has", async () => {
    // at t = 5, b is put at (3, 4): clear of a at (3, 0), on a at (3, 4)
    const put: Action = { time: 5, type: "updateBody", id: "b", x: 3, y: 4, v: [0, 0] };
    const { editor, client } = await open(scene(put), 2);
    expect(await editor.updateBody("a", { x: 3 })).toBeNull();
    await settled(client);
    const before = editor.doc;
    const err = await editor.updateBody("a", { y: 4 });
    expect(err).toMatch(
      /^The action at t = 5 s that updates body "b" \(actions\[3\]\): .*\(once this action is in place\)/,
    );
    await settled(client);
    expect(editor.doc).toEqual(before);
  });

  it("Undo while a merged edit is checked takes back that edit only: the action before it is as it was", async () => {
    // six discs bouncing near the floor of a box, computed to t = 40, an action at t = 30: the
    // check of an edit at t = 10 lasts a dozen events, each a round of the slow host
    const addE: Action = { time: 30, type: "addBody", id: "e", x: 50, y: 50, r: 1, m: 1 };
    const discs = [..."abcdfg"].map((id, k): [string, number, number, [number, number]] => [
      id,
      5 + 7 * k,
      5,
      [6 - k, 2 + k],
    ]);
    const h = await slowEditorAt(boxScene([addE], discs), 40, 10);
    expect(await h.editor.giveVelocity("b", [0, 1])).toBeNull();
    await settled(h.client);
    const first = h.editor.doc;
    expect(first.actions.filter((a) => a.time === 10)).toEqual([
      { time: 10, type: "giveVelocity", id: "b", v: [0, 1] },
    ]);
    const seen = checking(h);
    const edit = h.editor.updateBody("b", { x: 20 });
    await seen;
    // the host's scene holds the merged action while it is checked
    expect(h.client.getSnapshot().doc!.actions.filter((a) => a.time === 10)).toEqual([
      { time: 10, type: "updateBody", id: "b", v: [0, 1], x: 20 },
    ]);
    const undone = h.editor.undo();
    expect(await edit).not.toBeNull(); // taken back
    await undone;
    await settled(h.client);
    expect(h.editor.doc.actions).toEqual(first.actions);
    expect(h.editor.history.getState().past).toHaveLength(1);
    await h.editor.redo();
    await settled(h.client);
    expect(h.editor.doc.actions.filter((a) => a.time === 10)).toEqual([
      { time: 10, type: "updateBody", id: "b", v: [0, 1], x: 20 },
    ]);
  });
});
