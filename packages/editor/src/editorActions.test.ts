// Removing one action (an Event-log entry's) and naming the later action an edit would make invalid.
import { describe, expect, it } from "vitest";
import type { Action } from "./engineTypes";
import type { PageEvent } from "./remote/protocol";
import { settled, testEditor } from "./testing/harness";
import { sceneOf } from "./testing/scenes";

/** a at rest until t = 2, then a velocity; b placed at t = 3 at x = 10 (a is at x = 1 then). */
const ACTIONS: Action[] = [
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
  { time: 2, type: "giveVelocity", id: "a", v: [1, 0] },
  { time: 3, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 },
];

/** An action's time, type and id. */
const row = (a: Action) => [a.time, a.type, "id" in a ? a.id : null];

async function loaded() {
  const h = testEditor();
  expect(await h.editor.loadScene(sceneOf(ACTIONS), { undoable: false })).toBeNull();
  await settled(h.client);
  h.editor.ui.setState({ t: 1 });
  return h;
}

/** The Event log's entry for the action of `type` (as the host pages it). */
async function entry(h: Awaited<ReturnType<typeof loaded>>, type: string): Promise<PageEvent> {
  const page = await h.client.events(1, 20, 20, null);
  return page.events.find((e) => e.action === type)!;
}

describe("Editor.removeAction", () => {
  it("removes a later action as one undo step, the current time kept; undo brings it back", async () => {
    const h = await loaded();
    const e = await entry(h, "giveVelocity");
    expect(e.actionIndex).toBe(1);
    expect(
      await h.editor.removeAction(e.actionIndex!, { time: 2, type: "giveVelocity", id: "a" }),
    ).toBeNull();
    await settled(h.client);
    expect(h.editor.doc.actions.map(row)).toEqual([row(ACTIONS[0]!), row(ACTIONS[2]!)]);
    expect(h.editor.ui.getState().t).toBe(1);
    expect(h.client.getSnapshot().horizon).toBeGreaterThanOrEqual(11);
    expect(h.editor.history.getState().past).toHaveLength(1);
    await h.editor.undo();
    await settled(h.client);
    expect(h.editor.doc.actions.map(row)).toEqual(ACTIONS.map(row));
    expect(h.editor.doc.actions[1]).toEqual(ACTIONS[1]);
  });

  it("refuses a stale index (the scene changed since the log was read): nothing changes", async () => {
    const h = await loaded();
    const before = h.editor.doc;
    const err = await h.editor.removeAction(2, { time: 2, type: "giveVelocity", id: "a" });
    expect(err).toBe(
      'The scene changed since the Event log listed give velocity to "a" at t = 2 s: nothing was removed (try again).',
    );
    expect(h.editor.ui.getState().message).toEqual({ text: err, tone: "error" });
    expect(h.editor.doc).toBe(before);
    expect(h.editor.history.getState().past).toHaveLength(0);
  });

  it("a removal the engine refuses says which later action needs the removed one", async () => {
    const h = await loaded();
    const err = await h.editor.removeAction(0, { time: 0, type: "addBody", id: "a" });
    expect(err).toMatch(
      /^The action at t = 2 s that gives velocity to "a" \(actions\[0\]\.id\): no body "a"/,
    );
    expect(err).toMatch(/ \(remove it from the Event log\)$/);
    expect(h.editor.doc.actions).toHaveLength(3);
    expect(h.editor.history.getState().past).toHaveLength(0);
  });
});

describe("Editor.removeAction checks the actions after the removed one", () => {
  it("a removal that makes a later addBody overlap is refused and taken back (it was accepted and the computation stopped)", async () => {
    // a, at x = 10, moves away at t = 1 to leave room for b, placed at x = 10 at t = 3
    const h = testEditor();
    const actions: Action[] = [
      { time: 0, type: "addBody", id: "a", x: 10, y: 0, r: 1, m: 1 },
      { time: 1, type: "giveVelocity", id: "a", v: [5, 0] },
      { time: 3, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 },
    ];
    expect(await h.editor.loadScene(sceneOf(actions, 0), { undoable: false })).toBeNull();
    await settled(h.client);
    const horizon = h.client.getSnapshot().horizon;
    const before = h.editor.doc;
    const err = await h.editor.removeAction(1, { time: 1, type: "giveVelocity", id: "a" });
    expect(err).toMatch(
      /^The action at t = 3 s that adds disc "b" \(actions\[1\]\): body "b" would overlap body "a" at time 3/,
    );
    await settled(h.client);
    expect(h.editor.doc).toEqual(before);
    expect(h.editor.history.getState().past).toHaveLength(0);
    expect(h.client.getSnapshot()).toMatchObject({ horizon, stopped: null });
  });
});

describe("a refused edit names the later action it would make invalid", () => {
  it("an edit in the past that makes a later addBody overlap", async () => {
    const h = await loaded();
    // a moved to x = 10 at t = 1 is where b is placed at t = 3 (a moves off only at t = 2, by 1).
    const err = await h.editor.moveBody("a", 9, 0);
    expect(err).toMatch(
      /^The action at t = 3 s that adds disc "b" \(actions\[2\]\): .*\(once this action is in place\) \(remove it from the Event log\)$/,
    );
    expect(h.editor.ui.getState().message?.text).toBe(err);
  });

  it("a rewrite the engine refuses names the action in the list given", async () => {
    const h = await loaded();
    // A rewrite of the scene (as a rename or a removal loads it) with an action the engine refuses.
    const err = await h.editor.rewrite((doc) => ({
      ...doc,
      actions: [...doc.actions, { time: 5, type: "removeBody", id: "zz" }],
    }));
    expect(err).toMatch(
      /^The action at t = 5 s that removes body "zz" \(actions\[3\]\.id\): no body "zz".* \(remove it from the Event log\)$/,
    );
  });
});

describe("a refused edit names what the user edited, not the engine's path", () => {
  it("a cell's field (A r, A vx), a global (g) and a disc added where it overlaps", async () => {
    const h = await loaded();
    expect(await h.editor.updateBody("a", { r: -5 })).toBe("a r: must be a positive finite number (got -5)");
    expect(h.editor.ui.getState().message?.text).toBe("a r: must be a positive finite number (got -5)");
    expect(await h.editor.updateBody("a", { v: [Number.POSITIVE_INFINITY, 0] })).toBe(
      "a vx: must be a finite number (got Infinity)",
    );
    expect(await h.editor.updateBody("a", { v: [1e200, 0] })).toMatch(/^a vx: /);
    expect(await h.editor.setGlobal({ g: -1 })).toMatch(/^g: /);
    expect(await h.editor.addBody(1, 0, 1)).toMatch(/^a new disc here would overlap body "a" at time 1$/);
  });
});
