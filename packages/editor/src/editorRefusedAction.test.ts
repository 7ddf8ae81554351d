// A scene whose later action the engine refuses when the computation reaches it: which action that
// is (info.stoppedPath, in the scene the editor shows), and changing or removing it (review, session 30).
import { describe, expect, it } from "vitest";
import { entryOf, refusedAction } from "./doc/refusedAction";
import type { Action } from "./engineTypes";
import { settled, testEditor } from "./testing/harness";
import { sceneOf } from "./testing/scenes";

/** b3 is added at t = 1 over a (refused then); listed first, out of time order, as a file may list it. */
const ACTIONS: Action[] = [
  { time: 1, type: "addBody", id: "b3", x: 0.5, y: 0, r: 1, m: 1 },
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
  { time: 0, type: "addBody", id: "c", x: 50, y: 0, r: 1, m: 1, v: [1, 0] },
];

async function opened() {
  const h = testEditor();
  expect(await h.editor.loadScene(sceneOf(ACTIONS, 0))).toBeNull();
  await settled(h.client);
  return h;
}
type Opened = Awaited<ReturnType<typeof opened>>;
const refused = (h: Opened) => refusedAction(h.client.getSnapshot());
const b3 = (h: Opened) => h.editor.doc.actions.find((a) => "id" in a && a.id === "b3");

describe("a scene's refused later action", () => {
  it("is the action of the scene shown that the engine refused, whatever the order the file listed it in", async () => {
    const h = await opened();
    const r = refused(h);
    expect(r).not.toBeNull();
    expect(r?.action).toBe(h.editor.doc.actions[r?.index ?? -1]);
    expect(r).toMatchObject({
      path: "actions[2]",
      name: 'the action at t = 1 s that adds disc "b3"',
      reason: 'body "b3" would overlap body "a" at time 1',
    });
    expect(h.client.getSnapshot().horizon).toBe(1);
    expect(h.editor.ui.getState().message?.text).toContain(
      'The computation stopped at t = 1 s: the action at t = 1 s that adds disc "b3" (actions[2]): body "b3" would overlap body "a" at time 1. The Event log lists it as refused',
    );
  });

  it("changed to a value still refused: the change is refused, the scene stays stopped at the same refusal", async () => {
    const h = await opened();
    const r = refused(h)!;
    const before = h.editor.doc;
    const err = await h.editor.changeAction(r.index, entryOf(r.action), { ...r.action, x: 1 } as Action, "x");
    expect(err).toMatch(
      /^The action at t = 1 s that adds disc "b3" \(actions\[2\]\): body "b3" would overlap body "a"/,
    );
    await settled(h.client);
    expect(h.editor.doc).toEqual(before);
    expect(refused(h)).toMatchObject({ index: r.index, reason: r.reason });
  });

  it("changed to an accepted value: one undo step, and the rest of the scene computes on", async () => {
    const h = await opened();
    const r = refused(h)!;
    const steps = h.editor.history.getState().past.length;
    expect(
      await h.editor.changeAction(r.index, entryOf(r.action), { ...r.action, x: 5 } as Action, "x"),
    ).toBeNull();
    await settled(h.client);
    expect(b3(h)).toMatchObject({ x: 5 });
    expect(refused(h)).toBeNull();
    expect(h.client.getSnapshot().horizon).toBeGreaterThan(1);
    expect(h.editor.history.getState().past.length).toBe(steps + 1);
    expect(h.editor.ui.getState().message?.text).toBe(
      'Changed x of the action at t = 1 s that adds disc "b3" (Undo brings back the action as it was).',
    );
    await h.editor.undo();
    await settled(h.client);
    expect(b3(h)).toMatchObject({ x: 0.5 });
    expect(refused(h)?.reason).toBe(r.reason);
  });

  it("removed: one undo step, and the rest of the scene computes on", async () => {
    const h = await opened();
    const r = refused(h)!;
    expect(await h.editor.removeAction(r.index, entryOf(r.action))).toBeNull();
    await settled(h.client);
    expect(b3(h)).toBeUndefined();
    expect(refused(h)).toBeNull();
    expect(h.client.getSnapshot()).toMatchObject({ stopped: null, stoppedPath: null });
    expect(h.client.getSnapshot().horizon).toBeGreaterThan(1);
    await h.editor.undo();
    await settled(h.client);
    expect(refused(h)?.action).toEqual(b3(h));
  });

  it("its time changed puts it in its place among the others (the engine's indices stay the scene's)", async () => {
    const h = await opened();
    const r = refused(h)!;
    expect(
      await h.editor.changeAction(r.index, entryOf(r.action), { ...r.action, time: 0, x: 5 } as Action, "t"),
    ).toBeNull();
    await settled(h.client);
    expect(h.editor.doc.actions.map((a) => a.time)).toEqual([0, 0, 0]);
    expect(refused(h)).toBeNull();
  });
});
