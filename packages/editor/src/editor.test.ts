import { bouncingBalls, newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { F_FROM, F_UNTIL, F_VX, F_X, FRAME_STRIDE } from "./remote/protocol";
import { settled, testEditor } from "./testing/harness";
import { crushScene } from "./testing/scenes";

/** Newton's cradle: the striker (x = −6, v = 4) hits c1 (x = 0) at t = 1 exactly. */
async function cradle() {
  const h = testEditor();
  expect(await h.editor.loadScene(newtonsCradle(), { undoable: false })).toBeNull();
  await settled(h.client);
  return h;
}

async function bodyAt(h: Awaited<ReturnType<typeof cradle>>, id: string, t: number) {
  const f = await h.client.frame(t);
  const i = f.ids.indexOf(id) * FRAME_STRIDE;
  return { x: f.data[i + F_X]!, vx: f.data[i + F_VX]! };
}

describe("Editor over the worker protocol", () => {
  it("loading computes ahead by the Calculation settings and frames are exact", async () => {
    const h = await cradle();
    expect(h.client.getSnapshot().horizon).toBe(10);
    expect(await bodyAt(h, "striker", 0.5)).toEqual({ x: -4, vx: 4 });
    expect(await h.client.nextEvent(0)).toBe(1);
  });

  it("frames asked with a window carry each body's motion-law interval (up to its next event)", async () => {
    const h = await cradle();
    const f = await h.client.frame(0.5, 2);
    const i = f.ids.indexOf("striker") * FRAME_STRIDE;
    expect([f.data[i + F_FROM], f.data[i + F_UNTIL]]).toEqual([0, 1]);
    const still = await h.client.frame(0.5);
    expect([still.data[i + F_FROM], still.data[i + F_UNTIL]]).toEqual([0.5, 0.5]);
  });

  it("an edit is one undo step; undo and redo restore the scene", async () => {
    const h = await cradle();
    h.editor.ui.setState({ t: 0 });
    expect(await h.editor.updateBody("striker", { v: [8, 0] })).toBeNull();
    await settled(h.client);
    expect(await h.client.nextEvent(0)).toBe(0.5);
    expect(h.editor.history.getState().past.length).toBe(1);
    await h.editor.undo();
    await settled(h.client);
    expect(await h.client.nextEvent(0)).toBe(1);
    // the striker was the last body added at t = 0: the edit there changed its addBody (doc/mergeEdit.ts)
    expect(h.editor.ui.getState().message).toEqual({
      text: 'Undone: the change of v in add body "striker" at t = 0 s.',
      tone: "info",
    });
    await h.editor.redo();
    await settled(h.client);
    expect(await h.client.nextEvent(0)).toBe(0.5);
    expect(h.editor.ui.getState().message?.text).toBe(
      'Redone: the change of v in add body "striker" at t = 0 s.',
    );
  });

  it("an undo asked while an edit is still being applied waits for it and undoes it (redo brings it back)", async () => {
    const h = await cradle();
    h.editor.ui.setState({ t: 0 });
    const before = h.client.getSnapshot().doc!;
    const edit = h.editor.updateBody("striker", { v: [8, 0] });
    const undone = h.editor.undo();
    expect(await edit).toBeNull();
    await undone;
    await settled(h.client);
    expect(h.client.getSnapshot().doc).toEqual(before);
    expect(h.editor.history.getState()).toMatchObject({ past: [], future: [expect.anything()] });
    await h.editor.redo();
    await settled(h.client);
    expect(await h.client.nextEvent(0)).toBe(0.5);
    expect(h.editor.history.getState()).toMatchObject({ past: [before], future: [] });
  });

  it("a refused edit returns the engine's message and changes nothing", async () => {
    const h = await cradle();
    const before = h.client.getSnapshot().doc;
    const err = await h.editor.updateBody("c3", { r: -1 });
    expect(err).toMatch(/r: must be a positive finite number/);
    expect(h.editor.ui.getState().message?.text).toBe(err);
    expect(h.client.getSnapshot().doc).toBe(before);
    expect(h.editor.history.getState().past.length).toBe(0);
  });

  it("scrubbing, speed and selection are not undo steps", async () => {
    const h = await cradle();
    h.editor.setTime(3);
    h.editor.setSpeed(-1);
    h.editor.ui.setState({ selection: { kind: "body", id: "c1" } });
    h.editor.togglePlay();
    expect(h.editor.history.getState().past.length).toBe(0);
    expect(h.editor.ui.getState()).toMatchObject({ t: 3, speed: -1, playing: true });
  });

  it("deleting the selection removes the body at the current time only", async () => {
    const h = await cradle();
    h.editor.ui.setState({ t: 2, selection: { kind: "body", id: "c5" } });
    expect(await h.editor.deleteSelection()).toBeNull();
    await settled(h.client);
    expect((await h.client.frame(2.5)).ids).not.toContain("c5");
    expect((await h.client.frame(1.5)).ids).toContain("c5");
    expect(h.editor.ui.getState().selection).toBeNull();
    // said (a Delete said nothing, unlike the Event log's removal of an action)
    expect(h.editor.ui.getState().message).toEqual({
      text: 'Deleted body "c5" at t = 2 s (Undo brings it back).',
      tone: "info",
    });
  });

  it("renaming a body rewrites every action of it", async () => {
    const h = await cradle();
    expect(await h.editor.rename("body", "striker", "cue")).toBeNull();
    await settled(h.client);
    const ids = h.client.getSnapshot().doc!.actions.map((a) => ("id" in a ? a.id : ""));
    expect(ids).toContain("cue");
    expect(ids).not.toContain("striker");
    expect(await h.editor.rename("body", "cue", "c1")).toBe(
      'cue id: must not be the id of another body (got "c1")',
    );
  });

  it("a cue strike gives a velocity away from the click point", async () => {
    const h = await cradle();
    h.editor.ui.setState({ t: 0 });
    expect(await h.editor.strike("c5", [8, 0], [8, 0.5])).toBeNull();
    await settled(h.client);
    expect((await bodyAt(h, "c5", 0)).vx).toBe(0);
    const f = await h.client.frame(0.1);
    const i = f.ids.indexOf("c5") * FRAME_STRIDE;
    expect(f.data[i + F_VX + 1]).toBeLessThan(0);
  });

  it("a computation the engine refuses to continue (Zeno) ends with its message shown", async () => {
    const h = testEditor();
    h.editor.ui.setState((s) => ({ calc: { ...s.calc, useTime: false, useEvents: false } }));
    const err = await h.editor.loadScene(crushScene(), { undoable: false });
    expect(err).toBeNull();
    await settled(h.client, 30_000);
    expect(h.client.getSnapshot().stopped).toMatch(/Zeno/);
    const message = h.editor.ui.getState().message;
    expect(message?.tone).toBe("error");
    expect(message?.text).toMatch(/^The computation stopped at t = [\d.]+ s: .*Zeno/);
  });

  it("Cancel stops a computation without limit", async () => {
    const h = await cradle();
    h.editor.ui.setState((s) => ({ calc: { ...s.calc, useTime: false, useEvents: false } }));
    h.editor.computeAhead();
    h.editor.cancelCompute();
    await settled(h.client);
    expect(h.client.getSnapshot().computing).toBeNull();
  });

  it("a typed time past the horizon goes there once computed, unless the user scrubbed or edited meanwhile", async () => {
    // Review 7: t = 1e6 typed, then a disc added at t = 0 while it computed; the disc went in at
    // t = 0 and the view then jumped to the horizon the recompute happened to reach (t = 25,061).
    const h = testEditor();
    await h.editor.loadScene(bouncingBalls(), { undoable: false });
    await settled(h.client);
    const done = h.editor.goTo(200);
    await done;
    expect(h.editor.ui.getState().t).toBe(200);
    h.editor.setTime(0);
    const scrubbed = h.editor.goTo(400);
    h.editor.setTime(3); // the user scrubs back while it computes
    await scrubbed;
    expect(h.editor.ui.getState().t).toBe(3);
    h.editor.setTime(0);
    const edited = h.editor.goTo(600);
    expect(await h.editor.addBody(5, 8, 0.25)).toBeNull(); // a disc added at t = 0 while it computes
    await edited;
    await settled(h.client);
    expect(h.editor.ui.getState().t).toBe(0);
  });

  it("an engine that stopped answering is restarted with the same scene", async () => {
    const h = await cradle();
    h.editor.ui.setState({ t: 0.5 });
    h.host.handle = () => {}; // the old worker never answers again
    const lost = h.client.nextEvent(0).then(
      () => "answered",
      (e: Error) => e.message,
    );
    await new Promise((r) => setTimeout(r, 20));
    expect(h.client.stalledFor()).toBeGreaterThan(0);
    await h.editor.restartEngine();
    await settled(h.client);
    expect(await lost).toBe("engine restarted");
    expect(h.client.stalledFor()).toBe(0);
    expect(await bodyAt(h, "striker", 0.5)).toEqual({ x: -4, vx: 4 });
    expect(h.editor.ui.getState().t).toBe(0.5);
    expect(h.editor.ui.getState().message?.text).toBe("The engine was restarted.");
  });
});
