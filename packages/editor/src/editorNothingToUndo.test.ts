// Undo and Redo with nothing to take back say so (Ctrl+Shift+Z left the last "Redone: …" message up,
// as if it had redone something again: review, session 19); undoing a load names it as one (it read
// "Undone: a change of 19 actions").
import { newtonsCradle, originalDemo } from "@chapgame/engine";
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

  it("undoing and redoing a load says it was a load, not a change of so many actions", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    await h.editor.loadScene(originalDemo());
    await settled(h.client);
    const message = () => h.editor.ui.getState().message?.text;
    await h.editor.undo();
    await settled(h.client);
    expect(message()).toBe(
      `Undone: the scene loaded over yours; back to your scene (${newtonsCradle().actions.length} actions).`,
    );
    await h.editor.redo();
    await settled(h.client);
    expect(message()).toBe(`Redone: the scene loaded (${originalDemo().actions.length} actions).`);
  });
});
