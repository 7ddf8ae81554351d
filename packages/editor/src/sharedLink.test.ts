// A shared link opened in a tab already open: the scene of `#scene=...` is loaded as one undo step,
// a damaged code is said (the scene kept), and a hash that is no scene link is left alone.
import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { encodeSceneForUrl } from "./doc/persistence";
import { OPENED_SHARED, openSharedHash } from "./sharedLink";
import { settled, testEditor } from "./testing/harness";
import { sceneOf } from "./testing/scenes";

const lonely = sceneOf([{ time: 0, type: "addBody", id: "lonely", x: 0, y: 0, r: 1, m: 1 }], 0);

describe("openSharedHash", () => {
  it("loads the shared scene over the tab's one; Undo goes back", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    expect(await openSharedHash(h.editor, `#scene=${encodeSceneForUrl(lonely)}`)).toBe(true);
    await settled(h.client);
    expect(h.client.getSnapshot().doc?.actions.map((a) => ("id" in a ? a.id : a.type))).toEqual(["lonely"]);
    expect(h.editor.ui.getState().message?.text).toBe(OPENED_SHARED);
    await h.editor.undo();
    await settled(h.client);
    expect(h.client.getSnapshot().doc?.actions.length).toBe(newtonsCradle().actions.length);
  });

  it("a damaged code is said and the scene kept; another hash is not a link", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    expect(await openSharedHash(h.editor, "#scene=abc%25%25")).toBe(true);
    expect(h.editor.ui.getState().message?.text).toMatch(/^Shared link: /);
    expect(await openSharedHash(h.editor, "#section-2")).toBe(false);
    expect(h.client.getSnapshot().doc?.actions.length).toBe(newtonsCradle().actions.length);
  });
});
