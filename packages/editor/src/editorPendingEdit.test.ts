// An edit in the past is answered only once the host has checked the actions after it (host.ts,
// PendingEdit). These are the orderings a review of session 15 found wrong: the reply of a taken-
// back edit came before the info that took it back (the next queued change read the refused scene),
// the OK came before the info with the new horizon, and a restart during the check loaded the
// unchecked edit.
import { describe, expect, it } from "vitest";
import type { Action, SceneFile } from "./engineTypes";
import { settled, testEditor } from "./testing/harness";
import { boxScene } from "./testing/scenes";

const box: SceneFile = boxScene([{ time: 30, type: "addBody", id: "e", x: 50, y: 50, r: 1, m: 1 }]);
const blocker: Action = { time: 10, type: "addBody", id: "z", x: 50, y: 50.5, r: 1, m: 1 };
/** An editor with the box loaded and its history computed to t = 40. */
async function boxTo40() {
  const h = testEditor();
  await h.editor.loadScene(box, { undoable: false });
  await settled(h.client);
  await h.editor.goTo(40);
  await settled(h.client);
  return h;
}

const hasZ = (s: SceneFile | null | undefined) =>
  !!s?.actions.some((a) => a.type === "addBody" && a.id === "z");

describe("a taken-back edit and the next queued change", () => {
  it("an edit queued behind a refused edit in the past records the scene without it", async () => {
    const h = await boxTo40();
    h.editor.ui.setState({ t: 10 });
    const first = h.editor.edit([blocker]);
    const second = h.editor.edit([{ time: 10, type: "giveVelocity", id: "a", v: [1, 1] }]);
    expect(await first).toMatch(/overlap/);
    // taken back, the history restarts from 0: the second edit, at t = 10, must wait for it
    expect(await second).toMatch(/still being computed/);
    await settled(h.client);
    expect(hasZ(h.client.getSnapshot().doc)).toBe(false); // the host is right
    // and no undo step holds the refused one
    expect(h.editor.history.getState().past.some(hasZ)).toBe(false);
    await h.editor.undo();
    await settled(h.client);
    expect(hasZ(h.client.getSnapshot().doc)).toBe(false);
  });

  it("an undo queued behind a cancelled edit does not put the cancelled edit in Redo, nor undo the edit before", async () => {
    const h = await boxTo40();
    h.editor.ui.setState({ t: 10 });
    expect(await h.editor.edit([{ time: 10, type: "giveVelocity", id: "b", v: [0, 1] }])).toBeNull();
    await settled(h.client);
    h.editor.ui.setState({ t: 5 });
    const first = h.editor.edit([{ time: 5, type: "giveVelocity", id: "a", v: [1, 1] }]);
    for (let i = 0; i < 20; i++) await null; // the apply is posted (microtasks), not yet delivered
    h.editor.cancelCompute(); // arrives before the host's first round: the edit is taken back
    // Undo pressed after Cancel, before the cancel is answered: it is bound to the cancelled edit
    // (editorUndo.ts), which is not there to undo, so it undoes nothing.
    const undone = h.editor.undo();
    expect(await first).toMatch(/Cancelled/);
    await undone;
    await settled(h.client);
    const future = h.editor.history.getState().future;
    const cancelledInRedo = future.some((s) =>
      s.actions.some((a) => a.type === "giveVelocity" && a.id === "a" && a.time === 5),
    );
    expect(cancelledInRedo).toBe(false);
    const bKept = h.client.getSnapshot().doc!.actions.some((a) => a.type === "giveVelocity" && a.id === "b");
    expect(bKept).toBe(true);
  });
});

describe("a restart while an edit's later actions are being checked", () => {
  it("the restarted engine gets the unchecked edit that was answered 'engine restarted' and not recorded", async () => {
    const h = await boxTo40();
    const rev = h.client.getSnapshot().docRevision;
    h.editor.ui.setState({ t: 10 });
    const edit = h.editor.edit([blocker]); // refused once checked (e would overlap z at t = 30)
    while (h.client.getSnapshot().docRevision === rev) await new Promise((r) => setTimeout(r, 0));
    // the worker hangs inside the check (its first round never ends)
    (h.host as unknown as { round: () => void }).round = () => {};
    await h.editor.restartEngine();
    expect(await edit).toBe("engine restarted");
    await settled(h.client);
    expect(h.editor.history.getState().past.some(hasZ)).toBe(false); // not an undo step
    const snap = h.client.getSnapshot();
    expect({ z: hasZ(snap.doc), stopped: snap.stopped }).toEqual({ z: false, stopped: null });
  });
});

describe("the reply of a checked edit comes after the info with its horizon", () => {
  it("an edit queued behind an edit in the past is not refused as 'still being computed' once the host is past it", async () => {
    const h = await boxTo40();
    h.editor.ui.setState({ t: 5 });
    const first = h.editor.edit([{ time: 5, type: "giveVelocity", id: "a", v: [1, 1] }]);
    h.editor.ui.setState({ t: 10 });
    const second = h.editor.edit([{ time: 10, type: "giveVelocity", id: "b", v: [1, 1] }]);
    expect(await first).toBeNull();
    expect(await second).toBeNull();
  });
});
