import { describe, expect, it } from "vitest";
import { cradleEditor, settled } from "./testing/harness";
import { discsInRow, sceneOf } from "./testing/scenes";

/**
 * EditorSession.sceneSerial counts the scenes the current one replaced, so the tables can drop the
 * drafts of a scene no longer shown (a draft typed for "b1" of one scene must not apply to "b1" of
 * another): loads that replace the scene and the Undo and Redo of their steps count; edits,
 * renames, and the Undo and Redo of edits do not.
 */
describe("Editor.sceneSerial", () => {
  it("counts loads that replace the scene and the Undo and Redo of their steps, never an edit", async () => {
    const h = await cradleEditor();
    const serial = () => h.editor.sceneSerial.getState().serial;
    const start = serial();
    expect(await h.editor.updateBody("striker", { r: 0.4 })).toBeNull();
    await settled(h.client);
    expect(await h.editor.rename("body", "striker", "cue")).toBeNull();
    await settled(h.client);
    await h.editor.undo();
    await h.editor.redo();
    await settled(h.client);
    expect(serial(), "edits, a rename and their Undo and Redo keep the scene").toBe(start);

    expect(await h.editor.loadScene(sceneOf(discsInRow(["striker", "c1"])))).toBeNull();
    expect(serial(), "a load that replaces the scene").toBe(start + 1);
    await h.editor.undo();
    expect(serial(), "its Undo brings the scene before back").toBe(start + 2);
    await h.editor.redo();
    expect(serial(), "its Redo replaces it again").toBe(start + 3);
    await settled(h.client);
  });
});
