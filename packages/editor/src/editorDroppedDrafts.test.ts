import { describe, expect, it } from "vitest";
import { openPastedText } from "./doc/openScene";
import { sceneEditor, settled, type testEditor } from "./testing/harness";
import { discsInRow, sceneOf, twoDiscsAndPoint } from "./testing/scenes";

/**
 * A draft typed in a cell goes with its object (a delete, a rename, a removed add) or its scene (a
 * load, and the Undo or Redo of one): the message that step gives says so, naming what was typed
 * (openDrafts.ts). It vanished without a word. The cells record their drafts themselves
 * (EditableCell, panels/useOpenDraft.ts); here they are recorded as a cell of each row would.
 */
async function twoDiscs() {
  const h = await sceneEditor(twoDiscsAndPoint());
  const { drafts } = h.editor;
  drafts.set("a r", { label: "a r", text: "-1", owner: { kind: "body", id: "a", field: "r" } });
  drafts.set("b x", { label: "b x", text: "abc", owner: { kind: "body", id: "b", field: "x" } });
  drafts.set("p1 x", { label: "p1 x", text: "7", owner: { kind: "point", id: "p1", field: "x" } });
  drafts.set("g", { label: "g", text: "2", owner: null });
  return h;
}

const said = (h: ReturnType<typeof testEditor>) => h.editor.ui.getState().message?.text;

describe("a step that takes a draft away says so", () => {
  it("a delete names the drafts of the object deleted, and only those", async () => {
    const h = await twoDiscs();
    h.editor.ui.setState({ selection: { kind: "body", id: "a" } });
    expect(await h.editor.deleteSelection()).toBeNull();
    expect(said(h)).toBe(
      'Deleted body "a" at t = 0 s (Undo brings it back). Dropped the draft a r = -1, typed and not applied.',
    );
    h.editor.ui.setState({ selection: { kind: "point", id: "p1" } });
    h.editor.drafts.set("p1 x", null); // committed or closed meanwhile
    expect(await h.editor.deleteSelection()).toBeNull();
    expect(said(h)).toBe('Deleted point "p1" at t = 0 s (Undo brings it back).');
    await settled(h.client);
  });

  it("a rename names the drafts of the object's other cells, not its id cell's (the new name itself)", async () => {
    const h = await twoDiscs();
    h.editor.drafts.set("b id", {
      label: "b id",
      text: "ball",
      owner: { kind: "body", id: "b", field: "id" },
    });
    expect(await h.editor.rename("body", "b", "ball")).toBeNull();
    expect(said(h)).toBe(
      'Renamed body "b" to "ball" (Undo takes it back). Dropped the draft b x = "abc", typed and not applied.',
    );
    await settled(h.client);
  });

  it("removing an add from the Event log names the drafts of the object it made", async () => {
    const h = await twoDiscs();
    const index = h.editor.doc.actions.findIndex((a) => a.type === "addPoint");
    expect(await h.editor.removeAction(index, { time: 0, type: "addPoint", id: "p1" })).toBeNull();
    expect(said(h)).toBe(
      'Removed add point "p1" at t = 0 s from the scene (Undo brings it back). Dropped the draft p1 x = 7, typed and not applied.',
    );
    await settled(h.client);
  });

  it("a load that replaces the scene names every draft, in the message its caller gives", async () => {
    const h = await twoDiscs();
    expect(await openPastedText(h.editor, JSON.stringify(sceneOf(discsInRow(["c"]))))).toBeNull();
    expect(said(h)).toBe(
      'Pasted the scene. Undo returns to the scene you had before. Dropped the drafts a r = -1, b x = "abc", p1 x = 7 and 1 more, typed and not applied.',
    );
    await settled(h.client);
  });

  it("a load no message follows says it alone; one that keeps the scene (a reload of it) says nothing", async () => {
    const h = await twoDiscs();
    expect(await h.editor.loadScene(sceneOf(discsInRow(["c"])))).toBeNull();
    expect(said(h)).toBe(
      'Dropped the drafts a r = -1, b x = "abc", p1 x = 7 and 1 more, typed and not applied.',
    );
    await settled(h.client);
    h.editor.drafts.set("c r", { label: "c r", text: "0", owner: { kind: "body", id: "c", field: "r" } });
    h.editor.ui.setState({ message: null });
    expect(await h.editor.loadScene(h.editor.doc, { keepTime: true })).toBeNull();
    expect(said(h)).toBeUndefined();
    await settled(h.client);
  });

  it("the Undo of a load says it after what it undid", async () => {
    const h = await twoDiscs();
    expect(await h.editor.loadScene(sceneOf(discsInRow(["c"])))).toBeNull();
    await settled(h.client);
    for (const k of ["a r", "b x", "p1 x", "g"]) h.editor.drafts.set(k, null);
    h.editor.drafts.set("c r", { label: "c r", text: "0", owner: { kind: "body", id: "c", field: "r" } });
    await h.editor.undo();
    expect(said(h)).toMatch(/^Undone: .* Dropped the draft c r = 0, typed and not applied\.$/);
    await settled(h.client);
  });
});
