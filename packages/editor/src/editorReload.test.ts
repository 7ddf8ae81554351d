import { dilutedGas } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { F_VX, F_VY, FRAME_STRIDE } from "./remote/protocol";
import { cradleEditor, settled, testEditor } from "./testing/harness";

/**
 * Undo, redo and renames reload the scene at the current time: the host recomputes the history
 * from the start while the time stays (audit of session 15: the time field said 10 s while the
 * canvas and tables showed 1.86 s, and an edit then saved a velocity built from those values).
 */
describe("Editor while a reload's history is recomputed", () => {
  it("refuses an edit at a time the history has not reached yet, and accepts it once it has", async () => {
    const h = await cradleEditor();
    h.editor.ui.setState({ t: 0 });
    expect(await h.editor.updateBody("striker", { v: [8, 0] })).toBeNull();
    await settled(h.client);
    const edited = h.client.getSnapshot().doc;
    h.editor.ui.setState({ t: 5 });
    const undone = h.editor.undo();
    // asked at once, so it is applied right after the undo's load, before any recomputation
    const early = await h.editor.updateBody("c3", { v: [0, 1] });
    expect(early).toMatch(/still being computed up to t = 5 s/);
    expect(h.editor.ui.getState().message?.text).toBe(early);
    await undone;
    await settled(h.client);
    // the refusal no longer holds: the bar says so rather than keep it
    expect(h.editor.ui.getState().message).toEqual({
      text: "The history has reached t = 5 s: edits there are accepted now.",
      tone: "info",
    });
    const undoneDoc = h.client.getSnapshot().doc!;
    expect(undoneDoc).not.toEqual(edited);
    expect(h.editor.history.getState()).toMatchObject({ past: [], future: [edited] });
    expect(h.client.getSnapshot().horizon).toBeGreaterThanOrEqual(5);
    expect(await h.editor.updateBody("c3", { v: [0, 1] })).toBeNull();
  });

  it("a refusal the bar no longer shows is not brought back, nor replaced, when it lapses", async () => {
    const h = await cradleEditor();
    h.editor.ui.setState({ t: 0 });
    expect(await h.editor.updateBody("striker", { v: [8, 0] })).toBeNull();
    await settled(h.client);
    h.editor.ui.setState({ t: 5 });
    const undone = h.editor.undo();
    expect(await h.editor.updateBody("c3", { v: [0, 1] })).toMatch(/still being computed/);
    h.editor.info("Saved the file.");
    await undone;
    await settled(h.client);
    expect(h.editor.ui.getState().message).toEqual({ text: "Saved the file.", tone: "info" });
  });

  it('says so when the recomputation was cancelled short of the time (it said "still being computed")', async () => {
    const h = await cradleEditor();
    // what an undo at t = 50 leaves when its recomputation is cancelled at the horizon (10 s)
    h.editor.ui.setState({ t: 50 });
    expect(h.client.getSnapshot()).toMatchObject({ horizon: 10, computing: null });
    const err = await h.editor.updateBody("c3", { v: [0, 1] });
    expect(err).toBe(
      "The history reaches only t = 10 s (its computation was cancelled): go to a computed time, or type t = 50 s to compute up to it, then edit.",
    );
  });

  it("a second undo while the first one's history is recomputed keeps the whole range the user had", async () => {
    const h = testEditor();
    await h.editor.loadScene(dilutedGas({ n: 1500, packing: 0.1, seed: 3 }), { undoable: false });
    await settled(h.client);
    await h.editor.goTo(60);
    await settled(h.client);
    const far = h.client.getSnapshot().horizon;
    expect(far).toBeGreaterThanOrEqual(60);
    h.editor.ui.setState({ t: 0 });
    expect(await h.editor.giveVelocity("d0", [1, 0])).toBeNull();
    expect(await h.editor.giveVelocity("d1", [0, 1])).toBeNull();
    await settled(h.client);
    const first = h.editor.undo();
    const second = h.editor.undo();
    await Promise.all([first, second]);
    await settled(h.client, 60_000);
    expect(h.editor.history.getState().past).toEqual([]);
    expect(h.client.getSnapshot().horizon).toBeGreaterThanOrEqual(far);
  });

  it("a rename at a late time shows, once computed, the state at the current time", async () => {
    const h = await cradleEditor();
    h.editor.ui.setState({ t: 7 });
    expect(await h.editor.rename("body", "c3", "third")).toBeNull();
    await settled(h.client);
    expect(h.editor.ui.getState().t).toBe(7);
    expect(h.client.getSnapshot().horizon).toBeGreaterThanOrEqual(7);
    const f = await h.client.frame(7);
    expect(f.t).toBe(7);
    const i = f.ids.indexOf("third") * FRAME_STRIDE;
    expect([f.data[i + F_VX], f.data[i + F_VY]]).toEqual([0, 0]);
  });
});
