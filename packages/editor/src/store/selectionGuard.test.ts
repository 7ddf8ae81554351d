import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { settled, testEditor } from "../testing/harness";
import { createStore } from "./createStore";
import { dropStaleSelection, selectionExists } from "./selectionGuard";
import { createUiStore } from "./uiStore";

const scene = (actions: SceneFile["actions"]): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions,
});

describe("selection guard", () => {
  it("after Add body and undo, the removed body is no longer selected", async () => {
    const { editor, client } = testEditor();
    await editor.loadScene(scene([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }]), {
      undoable: false,
    });
    await settled(client);
    expect(await editor.addBody(5, 0, 1)).toBeNull();
    await settled(client);
    expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "b1" });
    await editor.undo();
    await settled(client);
    expect(editor.ui.getState().selection).toBeNull();
    // A selection whose object stays is kept through scene changes.
    editor.ui.setState({ selection: { kind: "body", id: "a" } });
    await editor.redo();
    await settled(client);
    expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "a" });
  });

  it("checks the kind as well as the id, and only when the scene changes", () => {
    const info = createStore({ doc: scene([]) as SceneFile | null, docRevision: 0 });
    const source = { getSnapshot: () => info.getState(), subscribe: (l: () => void) => info.subscribe(l) };
    const ui = createUiStore({ selection: { kind: "line", id: "w" } });
    dropStaleSelection(ui, source);
    const withBodyW = scene([{ time: 0, type: "addBody", id: "w", x: 0, y: 0, r: 1, m: 1 }]);
    expect(selectionExists(withBodyW, { kind: "body", id: "w" })).toBe(true);
    expect(selectionExists(withBodyW, { kind: "line", id: "w" })).toBe(false);
    info.setState({ doc: withBodyW, docRevision: 1 });
    expect(ui.getState().selection).toBeNull();
    // No change of the scene (a progress report): a selection is left as it is.
    ui.setState({ selection: { kind: "point", id: "nowhere" } });
    info.setState({ doc: withBodyW, docRevision: 1 });
    info.setState({ doc: null, docRevision: 1 });
    expect(ui.getState().selection).toEqual({ kind: "point", id: "nowhere" });
  });
});
