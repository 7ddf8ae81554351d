// The Undo of a Delete (key, toolbar or row ✕: each deletes the selection) selects the object again,
// as it was before the Delete; Redo deletes it again and selects nothing, as the Delete left it.
import { describe, expect, it } from "vitest";
import type { SceneFile } from "./engineTypes";
import type { Selection } from "./store/uiStore";
import { settled, testEditor } from "./testing/harness";

const scene: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
    { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
    { time: 0, type: "addLine", id: "w", p1: [10, -5], p2: [10, 5], kind: "segment" },
    { time: 0, type: "addPoint", id: "q", p: [0, 5] },
  ],
};

async function editor() {
  const h = testEditor();
  expect(await h.editor.loadScene(scene, { undoable: false })).toBeNull();
  await settled(h.client);
  return h;
}

describe("Undo and Redo of a Delete", () => {
  for (const sel of [
    { kind: "body", id: "a" },
    { kind: "line", id: "w" },
    { kind: "point", id: "q" },
  ] as NonNullable<Selection>[]) {
    it(`the Undo of the Delete of ${sel.kind} ${sel.id} selects it again; Redo selects nothing`, async () => {
      const { editor: ed, client } = await editor();
      ed.ui.setState({ t: 1, selection: sel });
      expect(await ed.deleteSelection()).toBeNull();
      await settled(client);
      expect(ed.ui.getState().selection).toBeNull();
      await ed.undo();
      await settled(client);
      expect(ed.ui.getState().selection).toEqual(sel);
      await ed.redo();
      await settled(client);
      expect(ed.ui.getState().selection).toBeNull();
      // and again: Undo selects it, however often
      await ed.undo();
      await settled(client);
      expect(ed.ui.getState().selection).toEqual(sel);
    });
  }

  it("Redo of a Delete keeps another object selected since; Undo of another edit keeps the selection", async () => {
    const { editor: ed, client } = await editor();
    ed.ui.setState({ t: 1, selection: { kind: "body", id: "a" } });
    expect(await ed.deleteSelection()).toBeNull();
    await settled(client);
    await ed.undo();
    await settled(client);
    ed.ui.setState({ selection: { kind: "body", id: "b" } });
    await ed.redo();
    await settled(client);
    expect(ed.ui.getState().selection).toEqual({ kind: "body", id: "b" });
    expect(await ed.updateBody("b", { v: [1, 0] })).toBeNull();
    await settled(client);
    ed.ui.setState({ selection: { kind: "line", id: "w" } });
    await ed.undo();
    await settled(client);
    expect(ed.ui.getState().selection).toEqual({ kind: "line", id: "w" });
  });
});
