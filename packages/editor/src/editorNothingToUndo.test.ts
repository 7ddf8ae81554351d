// Undo and Redo with nothing to take back say so (Ctrl+Shift+Z left the last "Redone: …" message up,
// as if it had redone something again: review, session 19).
import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { settled, testEditor } from "./testing/harness";

describe("Undo and Redo with nothing to do", () => {
  it("say so, after the last step too", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    const message = () => h.editor.ui.getState().message?.text;
    await h.editor.redo();
    expect(message()).toBe("Nothing to redo.");
    await h.editor.undo();
    expect(message()).toBe("Nothing to undo.");
    expect(await h.editor.edit([{ time: 0, type: "giveVelocity", id: "c1", v: [0, 1] }])).toBeNull();
    await settled(h.client);
    await h.editor.undo();
    await settled(h.client);
    expect(message()).toMatch(/^Undone: /);
    await h.editor.redo();
    await settled(h.client);
    expect(message()).toMatch(/^Redone: /);
    await h.editor.redo();
    expect(message()).toBe("Nothing to redo.");
  });
});
