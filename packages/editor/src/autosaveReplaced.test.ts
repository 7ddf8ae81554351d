// Autosave keeps the scene a load replaced (Clear, a preset, a file) beside the slot, so a reload
// brings it back as the step Undo goes back to; undone loads are not offered; near the storage quota
// the current scene comes first.
import { afterEach, describe, expect, it } from "vitest";
import { MAX_SLOTS, readReplaced, readSlot } from "./doc/autosaveSlots";
import { sceneText } from "./doc/sceneIo";
import { discs, ids, newProfile, type Profile, scene, stopProfile } from "./testing/tabProfile";

afterEach(stopProfile);

describe("autosave keeps the scene a load replaced", () => {
  const reload = (p: Profile, tab: { session: Storage; close(): void }) => {
    tab.close();
    return p.open(tab.session, true, true);
  };

  it("Clear then a reload: the scene is empty, Undo brings the work back (and says so)", async () => {
    const p = newProfile();
    const a = await p.open(undefined, true, true);
    await a.editor.loadScene(scene("work"));
    a.flush();
    expect(await a.editor.clear()).toBeNull();
    expect(a.ui().message).toEqual({ text: "Cleared the scene. Undo brings it back.", tone: "info" });
    const b = await reload(p, a);
    expect(b.editor.doc.actions).toEqual([]);
    expect(b.editor.history.getState().past.length).toBe(1);
    expect(b.ui().message?.text).toMatch(
      /^Restored the autosaved scene\. Undo brings back the scene it replaced at /,
    );
    await b.editor.undo();
    expect(ids(b.editor.doc)).toEqual(["work"]);
    // undone and reloaded: nothing to go back to (the replaced scene is the scene itself)
    const c = await reload(p, b);
    expect(ids(c.editor.doc)).toEqual(["work"]);
    expect(c.editor.history.getState().past.length).toBe(0);
  });

  it("Clear, then presets: the work is kept, not the empty scene nor the unedited preset between", async () => {
    const p = newProfile();
    const a = await p.open(undefined, true, true);
    await a.editor.loadScene(scene("work"));
    a.flush();
    await a.editor.clear();
    await a.editor.loadScene(scene("preset"), { reproducible: true });
    await a.editor.loadScene(scene("preset2"), { reproducible: true });
    a.flush();
    expect(ids(readReplaced(p.shared, a.autosave.tab)!.scene)).toEqual(["work"]);
    // an edit makes the preset work of its own: replacing it keeps it
    await a.editor.edit([{ time: 0, type: "updateBody", id: "preset2", x: 3 }]);
    await a.editor.clear();
    a.flush();
    expect(ids(readReplaced(p.shared, a.autosave.tab)!.scene)).toEqual(["preset2", "preset2"]);
    // a file (or a paste) loaded and replaced unedited is kept: it may exist nowhere else
    await a.editor.loadScene(scene("pasted"));
    await a.editor.clear();
    a.flush();
    expect(ids(readReplaced(p.shared, a.autosave.tab)!.scene)).toEqual(["pasted"]);
    const b = await reload(p, a);
    await b.editor.undo();
    expect(ids(b.editor.doc)).toEqual(["pasted"]);
  });

  it("a load undone is no longer offered after a reload; redone, it is again", async () => {
    const p = newProfile();
    const a = await p.open(undefined, true, true);
    await a.editor.loadScene(scene("work"), { undoable: false }); // (no load before Clear)
    a.flush();
    await a.editor.clear();
    a.flush();
    expect(ids(readReplaced(p.shared, a.autosave.tab)!.scene)).toEqual(["work"]);
    await a.editor.undo();
    await a.editor.edit([{ time: 0, type: "updateBody", id: "work", x: 5 }]);
    a.flush();
    // Clear was undone: nothing replaced the work in the end
    expect(readReplaced(p.shared, a.autosave.tab)).toBeNull();
    const b = await reload(p, a);
    expect(ids(b.editor.doc)).toEqual(["work", "work"]);
    expect(b.editor.history.getState().past.length).toBe(0);
    expect(b.ui().message).toBeNull();
    // undone then redone: kept again
    await b.editor.clear();
    await b.editor.undo();
    b.flush();
    expect(readReplaced(p.shared, b.autosave.tab)).toBeNull();
    await b.editor.redo();
    b.flush();
    const c = await reload(p, b);
    expect(c.editor.doc.actions).toEqual([]);
    await c.editor.undo();
    expect(ids(c.editor.doc)).toEqual(["work", "work"]);
    // Undo after the reload undoes that load too: the next reload has nothing to go back to
    await c.editor.edit([{ time: 0, type: "updateBody", id: "work", x: 7 }]);
    const d = await reload(p, c);
    expect(d.editor.history.getState().past.length).toBe(0);
  });

  it("undoing the latest load keeps the scene an earlier load, still done, replaced", async () => {
    const p = newProfile();
    const a = await p.open(undefined, true, true);
    await a.editor.loadScene(scene("work"));
    await a.editor.clear();
    await a.editor.edit(scene("disc").actions);
    await a.editor.clear();
    a.flush();
    expect(ids(readReplaced(p.shared, a.autosave.tab)!.scene)).toEqual(["disc"]);
    await a.editor.undo();
    a.flush();
    expect(ids(readReplaced(p.shared, a.autosave.tab)!.scene)).toEqual(["work"]);
    const b = await reload(p, a);
    expect(ids(b.editor.doc)).toEqual(["disc"]);
    await b.editor.undo();
    expect(ids(b.editor.doc)).toEqual(["work"]);
  });

  it("the scene replaced within the autosave's quiet delay is kept by the save on leaving the page", async () => {
    const p = newProfile();
    const a = await p.open(undefined, true, true);
    await a.editor.loadScene(scene("work"));
    a.flush();
    await a.editor.clear(); // reloaded at once: no timer has run
    const b = await reload(p, a);
    await b.editor.undo();
    expect(ids(b.editor.doc)).toEqual(["work"]);
  });

  it("a pruned slot takes its replaced scene with it", async () => {
    const p = newProfile();
    const a = await p.open(undefined, true, true);
    await a.editor.loadScene(scene("work"));
    a.flush();
    await a.editor.clear();
    a.close();
    for (let i = 0; i < MAX_SLOTS; i++) {
      const t = await p.open();
      await t.editor.loadScene(scene(`s${i}`));
      t.flush();
    }
    expect(readSlot(p.shared, a.autosave.tab)).toBeNull();
    expect(readReplaced(p.shared, a.autosave.tab)).toBeNull();
  });

  describe("near the storage quota the current scene comes first", () => {
    // room for two scenes of 40 discs, not for one of 40 and one of 60
    const quota = () => 2 * sceneText(discs("work", 40)).length + 500;

    it("a load: the new scene is saved, the scene it replaced is dropped (and said so)", async () => {
      const p = newProfile(quota());
      const a = await p.open(undefined, true, true);
      await a.editor.loadScene(discs("work", 40));
      a.flush();
      await a.editor.loadScene(discs("file", 60));
      a.flush();
      expect(readSlot(p.shared, a.autosave.tab)?.scene.actions.length).toBe(60);
      expect(readReplaced(p.shared, a.autosave.tab)).toBeNull();
      expect(a.ui().message).toEqual({
        text: "Autosave could not keep the scene you replaced (the browser's storage is full): Undo brings it back in this tab, but not after a reload.",
        tone: "error",
      });
      await a.editor.undo(); // in this tab it is still there
      expect(a.editor.doc.actions.length).toBe(40);
      await a.editor.redo();
      const b = await reload(p, a);
      expect(b.editor.doc.actions.length).toBe(60);
      expect(b.editor.history.getState().past.length).toBe(0);
    });

    it("an edit that no longer fits beside the replaced scene: the replaced scene gives its space up", async () => {
      const p = newProfile(quota());
      const a = await p.open(undefined, true, true);
      await a.editor.loadScene(discs("work", 40));
      a.flush();
      await a.editor.loadScene(scene("file", -10));
      a.flush();
      expect(readReplaced(p.shared, a.autosave.tab)?.scene.actions.length).toBe(40);
      expect(await a.editor.edit(discs("more", 60).actions)).toBeNull();
      a.flush();
      expect(readSlot(p.shared, a.autosave.tab)?.scene.actions.length).toBe(61);
      expect(readReplaced(p.shared, a.autosave.tab)).toBeNull();
      expect(a.ui().message?.text).toMatch(
        /^Autosave could not keep the scene you replaced .*not after a reload\.$/,
      );
      const b = await reload(p, a);
      expect(b.editor.doc.actions.length).toBe(61);
    });
  });
});
