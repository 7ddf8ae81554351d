// @vitest-environment jsdom
// A refused autosave at start (review, session 19: the default scene replaced the user's without a
// word, and the next edit overwrote the slot): the scene is kept and announced, offered as a file,
// announced again at the next start until dismissed; Dismiss forgets it.
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { TabAutosave } from "../autosave";
import { firstScene, loadFirstScene } from "../boot";
import { writeSlot } from "../doc/autosaveSlots";
import { readRefused, refusedKey } from "../doc/refusedScene";
import { sceneText } from "../doc/sceneIo";
import { EditorContext } from "../EditorContext";
import type { SceneFile } from "../engineTypes";
import { settled, testEditor } from "../testing/harness";
import { memoryStorage } from "../testing/memoryStorage";
import { REFUSED_NAME, RefusedSceneNotice } from "./RefusedSceneNotice";

afterEach(cleanup);

/** Parses as a scene file, but the engine refuses it: d is removed at 0.1, then updated at 400. */
const refusedScene: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [
    { time: 0, type: "addBody", id: "d", x: 0, y: 0, r: 1, m: 1 },
    { time: 0.1, type: "removeBody", id: "d" },
    { time: 400, type: "updateBody", id: "d", x: 5 },
  ],
};

/** A tab starting as boot.ts does, over `local` (its own slot written as "tab1"). */
async function start(local: Storage) {
  const session = memoryStorage();
  session.setItem("chapgame.editor.tab", "tab1");
  const autosave = new TabAutosave({ local, session, now: () => 5, newTabId: () => "tab2", channel: null });
  const h = testEditor();
  await loadFirstScene(h.editor, firstScene("", autosave), local);
  await settled(h.client);
  return h;
}

describe("a refused autosave at start", () => {
  it("loads the default scene, keeps the refused one and says why; the next start says it again", async () => {
    const local = memoryStorage();
    expect(writeSlot(local, "tab1", sceneText(refusedScene), 1)).toBeNull();
    const h = await start(local);
    expect(h.client.getSnapshot().doc?.actions.some((a) => "id" in a && a.id === "d")).toBe(false);
    const reason = h.editor.ui.getState().refusedScene?.reason ?? "";
    expect(reason).toMatch(/no body "d"/);
    expect(readRefused(local, "tab1")?.text).toBe(sceneText(refusedScene));
    // a start after the slot was overwritten (an edit of the default scene): still announced
    writeSlot(local, "tab1", sceneText({ ...refusedScene, actions: [] }), 2);
    const again = await start(local);
    expect(again.editor.ui.getState().refusedScene?.reason).toBe(reason);
  });

  it("the notice offers the kept scene as a file, and Dismiss forgets it", async () => {
    const local = memoryStorage();
    writeSlot(local, "tab1", sceneText(refusedScene), 1);
    const h = await start(local);
    const made: Blob[] = [];
    URL.createObjectURL = vi.fn((b: Blob) => {
      made.push(b);
      return "blob:kept";
    });
    URL.revokeObjectURL = vi.fn();
    const names: string[] = [];
    const click = vi.spyOn(HTMLAnchorElement.prototype, "click").mockImplementation(function (
      this: HTMLAnchorElement,
    ) {
      names.push(this.download);
    });
    render(
      <EditorContext.Provider value={h.editor}>
        <RefusedSceneNotice local={local} />
      </EditorContext.Provider>,
    );
    const notice = screen.getByRole("alert", { name: "Autosaved scene refused" });
    expect(notice.textContent).toMatch(/could not be opened: .*no body "d".*kept until you dismiss/);
    fireEvent.click(screen.getByRole("button", { name: "Save it as a file" }));
    expect(names).toEqual([REFUSED_NAME]);
    expect(await made[0]?.text()).toBe(sceneText(refusedScene));
    act(() => {
      fireEvent.click(screen.getByRole("button", { name: "Dismiss" }));
    });
    expect(screen.queryByRole("alert", { name: "Autosaved scene refused" })).toBeNull();
    expect(local.getItem(refusedKey("tab1"))).toBeNull();
    click.mockRestore();
  });

  it("kept per tab: another tab's refusal neither replaces it nor shows in a fresh tab", async () => {
    const local = memoryStorage();
    writeSlot(local, "tab1", sceneText(refusedScene), 1);
    await start(local);
    const other = {
      ...refusedScene,
      actions: [...refusedScene.actions, { time: 500, type: "removeBody", id: "q" }],
    };
    writeSlot(local, "tabB", sceneText(other as SceneFile), 2);
    const sessionB = memoryStorage();
    sessionB.setItem("chapgame.editor.tab", "tabB");
    const autosaveB = new TabAutosave({
      local,
      session: sessionB,
      now: () => 6,
      newTabId: () => "x",
      channel: null,
    });
    const b = testEditor();
    await loadFirstScene(b.editor, firstScene("", autosaveB), local);
    expect(readRefused(local, "tab1")?.text).toBe(sceneText(refusedScene));
    expect(readRefused(local, "tabB")?.text).toBe(sceneText(other as SceneFile));
    // a fresh tab (a new id, no slot of its own) is told nothing
    const fresh = new TabAutosave({
      local,
      session: memoryStorage(),
      now: () => 7,
      newTabId: () => "tabF",
      channel: null,
    });
    const f = testEditor();
    await loadFirstScene(f.editor, firstScene("", fresh), local);
    expect(f.editor.ui.getState().refusedScene).toBeNull();
  });

  it("when the storage cannot keep it, the notice still offers the scene from memory", async () => {
    const local = memoryStorage();
    writeSlot(local, "tab1", sceneText(refusedScene), 1);
    const full: Storage = {
      setItem(k: string, v: string) {
        if (k.startsWith("chapgame.editor.refused")) throw new DOMException("full", "QuotaExceededError");
        local.setItem(k, v);
      },
      getItem: (k: string) => local.getItem(k),
      removeItem: (k: string) => local.removeItem(k),
      key: (i: number) => local.key(i),
      clear: () => local.clear(),
      get length() {
        return local.length;
      },
    };
    const h = await start(full);
    expect(h.editor.ui.getState().refusedScene).toMatchObject({ tab: null, text: sceneText(refusedScene) });
    render(
      <EditorContext.Provider value={h.editor}>
        <RefusedSceneNotice local={full} />
      </EditorContext.Provider>,
    );
    expect(screen.getByRole("alert", { name: "Autosaved scene refused" }).textContent).toMatch(
      /could not be kept/,
    );
    expect(screen.getByRole("button", { name: "Save it as a file" })).toBeTruthy();
  });
});
