// The scene's title (Editor.setTitle, host op `meta`): one undo step, nothing recomputed, saved in
// the file, the name Save file suggests when the scene has no file of the author's.
import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { saveNameFor } from "./doc/saveName";
import { sceneText } from "./doc/sceneIo";
import type { RequestMessage } from "./remote/protocol";
import { settled, testEditor } from "./testing/harness";

/** Newton's cradle loaded as a preset would be, computed to its horizon; the ops the host is sent. */
async function cradle(options: { name: string; preset: boolean }) {
  const h = testEditor();
  const sent: string[] = [];
  const handle = h.host.handle.bind(h.host);
  h.host.handle = (m: RequestMessage) => {
    sent.push(m.op);
    handle(m);
  };
  expect(await h.editor.loadScene(newtonsCradle(), { undoable: false, ...options })).toBeNull();
  await settled(h.client);
  sent.length = 0;
  return { ...h, sent };
}

const suggested = (h: Awaited<ReturnType<typeof cradle>>) => saveNameFor(h.editor.names.name, h.editor.doc);

describe("Editor.setTitle", () => {
  it("sets meta.title as one undo step without recomputing; Undo and Redo neither", async () => {
    const h = await cradle({ name: "cradle.chapgame.json", preset: false });
    const horizon = h.client.getSnapshot().horizon;
    const actions = sceneText({ ...h.editor.doc, meta: undefined });
    h.editor.ui.setState({ t: 3 });
    expect(await h.editor.setTitle("  Five balls ")).toBeNull();
    expect(h.editor.doc.meta).toEqual({ title: "Five balls" });
    expect(JSON.parse(sceneText(h.editor.doc)).meta).toEqual({ title: "Five balls" });
    expect(h.editor.history.getState().past.length).toBe(1);
    expect(h.editor.ui.getState().message?.text).toBe(
      'Titled the scene "Five balls": Save file suggests cradle.chapgame.json (the scene\'s own file). Undo takes it back.',
    );
    await h.editor.undo();
    expect(h.editor.doc.meta).toBeUndefined();
    expect(h.editor.ui.getState().message?.text).toBe('Undone: the title set to "Five balls".');
    await h.editor.redo();
    expect(h.editor.doc.meta).toEqual({ title: "Five balls" });
    expect(h.editor.ui.getState().message?.text).toBe('Redone: the title set to "Five balls".');
    // nothing was loaded or computed again: the history, the actions and the time are as they were
    expect(h.sent.filter((op) => op === "load" || op === "compute")).toEqual([]);
    expect(h.client.getSnapshot().horizon).toBe(horizon);
    expect(sceneText({ ...h.editor.doc, meta: undefined })).toBe(actions);
    expect(h.editor.ui.getState().t).toBe(3);
  });

  it("the same title again is no undo step; a blank one removes it; the rest of meta stays", async () => {
    const h = testEditor();
    const scene = { ...newtonsCradle(), meta: { view: { zoom: 2 }, title: "A" } };
    expect(await h.editor.loadScene(scene, { undoable: false })).toBeNull();
    await settled(h.client);
    expect(await h.editor.setTitle(" A ")).toBeNull();
    expect(h.editor.history.getState().past.length).toBe(0);
    expect(await h.editor.setTitle("   ")).toBeNull();
    expect(h.editor.doc.meta).toEqual({ view: { zoom: 2 } });
    expect(h.editor.ui.getState().message?.text).toMatch(/^Removed the scene's title: Save file suggests /);
    await h.editor.undo();
    expect(h.editor.doc.meta).toEqual({ view: { zoom: 2 }, title: "A" });
  });

  it("names the file Save suggests for a preset's scene, not for the author's own file", async () => {
    const preset = await cradle({ name: "newtons-cradle.chapgame.json", preset: true });
    await preset.editor.setTitle("My cradle");
    expect(suggested(preset)).toBe("my-cradle.chapgame.json");
    expect(preset.editor.ui.getState().message?.text).toBe(
      'Titled the scene "My cradle": Save file suggests my-cradle.chapgame.json. Undo takes it back.',
    );
    // Undo goes back to the preset's name, Redo to the title's
    await preset.editor.undo();
    expect(suggested(preset)).toBe("newtons-cradle.chapgame.json");
    await preset.editor.redo();
    expect(suggested(preset)).toBe("my-cradle.chapgame.json");
    // a name the author picked when saving is kept by a later title
    preset.editor.names.saved("mine.json");
    await preset.editor.setTitle("Renamed");
    expect(suggested(preset)).toBe("mine.json");

    const own = await cradle({ name: "cradle.json", preset: false });
    await own.editor.setTitle("My cradle");
    expect(suggested(own)).toBe("cradle.json");
  });

  it("a title set then an edit: Undo of the edit keeps the title, Undo again removes it", async () => {
    const h = await cradle({ name: "c.json", preset: false });
    h.editor.ui.setState({ t: 0 });
    await h.editor.setTitle("T");
    expect(await h.editor.updateBody("c1", { r: 0.9 })).toBeNull();
    expect(h.editor.doc.meta).toEqual({ title: "T" });
    await h.editor.undo();
    expect(h.editor.doc.meta).toEqual({ title: "T" });
    expect(h.editor.doc.actions.find((a) => a.type === "addBody" && a.id === "c1")).toMatchObject({ r: 1 });
    await h.editor.undo();
    expect(h.editor.doc.meta).toBeUndefined();
  });
});
