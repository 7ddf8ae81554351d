import { afterEach, describe, expect, it } from "vitest";
import { ADOPT_AFTER_MS, openNewerWork, TAB_KEY, TabAutosave } from "./autosave";
import { firstScene, loadFirstScene } from "./boot";
import { LEGACY_KEY, listSlots, MAX_SLOTS, readReplaced, readSlot, slotKey } from "./doc/autosaveSlots";
import { sceneText } from "./doc/sceneIo";
import { EMPTY_SCENE } from "./editor";
import type { SceneFile } from "./engineTypes";
import { settled, testEditor } from "./testing/harness";
import { memoryStorage } from "./testing/memoryStorage";

const scene = (id: string, x = 0): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id, x, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] }],
});
/** A scene of `n` discs (ids `<id>0`...), to fill the storage. */
const discs = (id: string, n: number): SceneFile => ({
  ...scene(id),
  actions: Array.from({ length: n }, (_, i) => ({ ...scene(`${id}${i}`, 3 * i).actions[0]! })),
});
const ids = (s: SceneFile) => s.actions.map((a) => ("id" in a ? a.id : a.type));

/**
 * A browser profile: one localStorage shared by its tabs. Each tab sees it through its own Storage
 * object, and a write by one tab fires a `storage` event in every other tab (as browsers do).
 */
function profile(quota = Number.POSITIVE_INFINITY) {
  const shared = memoryStorage(quota);
  const tabs: { win: EventTarget; local: Storage }[] = [];
  let clock = 1_000;
  const stops: (() => void)[] = [];
  let n = 0;
  const notify = (from: Storage, key: string, newValue: string | null) => {
    for (const t of tabs)
      if (t.local !== from)
        t.win.dispatchEvent(Object.assign(new Event("storage"), { key, newValue, storageArea: t.local }));
  };
  const localFor = (): Storage => {
    const local: Storage = {
      get length() {
        return shared.length;
      },
      key: (i) => shared.key(i),
      getItem: (k) => shared.getItem(k),
      setItem: (k, v) => {
        shared.setItem(k, v);
        notify(local, k, v);
      },
      removeItem: (k) => {
        shared.removeItem(k);
        notify(local, k, null);
      },
      clear: () => shared.clear(),
    };
    return local;
  };
  /** Opens a tab (a reload when `session` is a tab's sessionStorage) and starts its autosave. */
  async function open(session: Storage = memoryStorage(), channel = true, asBoot = false) {
    const win = new EventTarget();
    const local = localFor();
    tabs.push({ win, local });
    const bc = channel ? new BroadcastChannel("test.tabs") : null;
    const autosave = new TabAutosave({
      local,
      session,
      now: () => ++clock,
      newTabId: () => `tab${++n}`,
      channel: bc as never,
    });
    const h = testEditor();
    // `asBoot`: as boot.ts starts (the previous scene and the default preset too), else simplified
    const first = asBoot ? firstScene("", autosave) : null;
    const restored = asBoot ? null : autosave.restore();
    if (first) await loadFirstScene(h.editor, first);
    // (boot loads the default preset when there is no autosave)
    else await h.editor.loadScene(restored?.slot.scene ?? EMPTY_SCENE, { undoable: false });
    await settled(h.client);
    const stop = autosave.attach(h.editor, win as Window);
    stops.push(stop);
    const flush = () => win.dispatchEvent(new Event("pagehide"));
    /** Closes the tab (after the pagehide flush): it no longer hears or answers anything. */
    const close = () => {
      flush();
      stop();
      tabs.splice(
        tabs.findIndex((t) => t.win === win),
        1,
      );
    };
    const ui = () => h.editor.ui.getState();
    return { ...h, autosave, session, local, win, restored, flush, close, ui };
  }
  const stop = () => {
    for (const s of stops) s();
  };
  return { shared, open, stop };
}

let current: ReturnType<typeof profile> | null = null;
const newProfile = (quota?: number) => {
  current = profile(quota);
  return current;
};
afterEach(() => current?.stop());

describe("autosave per tab", () => {
  it("two tabs keep their own slots: neither overwrites the other, and each reload gets its own back", async () => {
    const p = newProfile();
    const a = await p.open();
    const b = await p.open();
    expect(a.autosave.tab).not.toBe(b.autosave.tab);
    await a.editor.loadScene(scene("fromA"));
    a.flush();
    await b.editor.loadScene(scene("fromB"));
    b.flush(); // B saved last
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["fromA"]);
    expect(ids(readSlot(p.shared, b.autosave.tab)!.scene)).toEqual(["fromB"]);
    const aAgain = await p.open(a.session); // A reloads: its own scene, not the newer one of B
    expect(aAgain.autosave.tab).toBe(a.autosave.tab);
    expect(ids(aAgain.editor.doc)).toEqual(["fromA"]);
    expect(aAgain.restored?.note).toBeNull();
    // ... and it is told that B saved newer work
    expect(aAgain.autosave.newerOther()?.tab).toBe(b.autosave.tab);
  });

  it("a fresh tab restores the most recently saved scene (and saves into a slot of its own)", async () => {
    const p = newProfile();
    const a = await p.open();
    await a.editor.loadScene(scene("older"));
    a.flush();
    const b = await p.open();
    await b.editor.loadScene(scene("newest"));
    b.flush();
    const c = await p.open();
    expect(c.autosave.reloaded).toBe(false);
    expect(ids(c.editor.doc)).toEqual(["newest"]);
    expect(c.autosave.newerOther()).toBeNull(); // it has the newest already
    await c.editor.loadScene(scene("fromC"));
    c.flush();
    expect(ids(readSlot(p.shared, b.autosave.tab)!.scene)).toEqual(["newest"]);
    expect(listSlots(p.shared).length).toBe(3);
  });

  it("the single autosave of an earlier version is restored by a fresh tab and kept", async () => {
    const p = newProfile();
    p.shared.setItem(LEGACY_KEY, sceneText(scene("legacy")));
    const a = await p.open();
    expect(ids(a.editor.doc)).toEqual(["legacy"]);
    await a.editor.loadScene(scene("mine"));
    a.flush();
    expect(p.shared.getItem(LEGACY_KEY)).toBeNull();
    expect(ids(readSlot(p.shared, "v1")!.scene)).toEqual(["legacy"]); // the old work is kept
  });

  it("a tab is told when another tab saves newer work; Open loads it as one undo step", async () => {
    const p = newProfile();
    const a = await p.open();
    await a.editor.loadScene(scene("mine"));
    a.flush();
    const b = await p.open();
    expect(a.ui().newerWork).toBeNull(); // B restored A's scene: nothing new
    await b.editor.edit([{ time: 0, type: "updateBody", id: "mine", x: 5 }]);
    b.flush();
    expect(a.ui().newerWork).toEqual({ tab: b.autosave.tab, savedAt: expect.any(Number) });
    expect(await openNewerWork(a.editor, p.shared, b.autosave.tab)).toBeNull();
    await settled(a.client);
    expect(a.editor.doc.actions.at(-1)).toMatchObject({ type: "updateBody", x: 5 });
    expect(a.ui().newerWork).toBeNull();
    expect(a.ui().message?.text).toMatch(/^Opened the scene another tab saved at .*Undo returns/);
    await a.editor.undo();
    expect(a.editor.doc.actions.length).toBe(1);
  });

  it("Dismiss mutes that tab; a tab whose slot is gone cannot be opened and the notice goes", async () => {
    const p = newProfile();
    const a = await p.open();
    const b = await p.open();
    const c = await p.open();
    await b.editor.loadScene(scene("b1"));
    b.flush();
    expect(a.ui().newerWork?.tab).toBe(b.autosave.tab);
    a.editor.ui.setState({ newerWork: null }); // Dismiss
    await b.editor.loadScene(scene("b2"));
    b.flush();
    expect(a.ui().newerWork).toBeNull();
    await c.editor.loadScene(scene("c1"));
    c.flush();
    expect(a.ui().newerWork?.tab).toBe(c.autosave.tab); // another tab is still announced
    // C is closed and its slot removed (pruned by B, say): the notice goes, there is nothing to open
    c.close();
    b.local.removeItem(slotKey(c.autosave.tab));
    expect(a.ui().newerWork).toBeNull();
    expect(await openNewerWork(a.editor, p.shared, c.autosave.tab)).toMatch(/no longer stored/);
    expect(a.ui().message?.tone).toBe("error");
  });

  it(`slots are pruned to ${MAX_SLOTS} (the oldest first); a live tab whose slot was pruned writes it again at once`, async () => {
    const p = newProfile();
    const open = async (id: string) => {
      const t = await p.open(memoryStorage(), false);
      await t.editor.loadScene(scene(id));
      t.flush();
      return t;
    };
    const closed = await open("closedLongAgo");
    closed.close();
    const a = await open("keepMe");
    const others = [];
    for (let i = 1; i < MAX_SLOTS; i++) others.push(await open(`o${i}`));
    // the eighth other tab's save pruned the oldest slot, the closed tab's
    expect(listSlots(p.shared).length).toBe(MAX_SLOTS);
    expect(readSlot(p.shared, closed.autosave.tab)).toBeNull();
    // one more: the oldest slot is now A's, whose tab is open: A writes it again (9 open tabs, 9 slots)
    others.push(await open("o8"));
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["keepMe"]);
    expect(listSlots(p.shared).length).toBe(MAX_SLOTS + 1);
    for (const t of others) expect(readSlot(p.shared, t.autosave.tab), t.autosave.tab).not.toBeNull();
  });

  it("a tab duplicated by the browser (same id in its copied sessionStorage) takes a new id", async () => {
    const p = newProfile();
    const a = await p.open();
    await a.editor.loadScene(scene("original"));
    a.flush();
    const copied = memoryStorage();
    copied.setItem(TAB_KEY, a.session.getItem(TAB_KEY)!);
    const dup = await p.open(copied);
    expect(ids(dup.editor.doc)).toEqual(["original"]); // it shows what the tab showed
    await expect.poll(() => dup.autosave.tab, { timeout: 2000 }).not.toBe(a.autosave.tab);
    expect(copied.getItem(TAB_KEY)).toBe(dup.autosave.tab);
    await dup.editor.loadScene(scene("duplicate"));
    dup.flush();
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["original"]);
    expect(ids(readSlot(p.shared, dup.autosave.tab)!.scene)).toEqual(["duplicate"]);
  });

  it("a fresh tab that restored the scene of a closed tab carries on in its slot (no second copy)", async () => {
    const p = newProfile();
    const a = await p.open();
    await a.editor.loadScene(scene("yesterday"));
    a.close();
    const b = await p.open();
    expect(ids(b.editor.doc)).toEqual(["yesterday"]);
    await expect.poll(() => b.autosave.tab, { timeout: 3000 }).toBe(a.autosave.tab);
    expect(b.session.getItem(TAB_KEY)).toBe(a.autosave.tab);
    await b.editor.loadScene(scene("today"));
    b.flush();
    expect(listSlots(p.shared).map((s) => s.tab)).toEqual([a.autosave.tab]);
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["today"]);
  });

  it("a page back from the back-forward cache whose slot was taken over meanwhile moves to a new one", async () => {
    const p = newProfile();
    const a = await p.open();
    await a.editor.loadScene(scene("cached"));
    a.flush(); // pagehide: into the cache (its script stops, it answers no hello)
    const channelA = (a.autosave as unknown as { env: { channel: BroadcastChannel } }).env.channel;
    const onmessage = channelA.onmessage;
    channelA.onmessage = null;
    const b = await p.open();
    await expect.poll(() => b.autosave.tab, { timeout: 3000 }).toBe(a.autosave.tab);
    channelA.onmessage = onmessage;
    a.win.dispatchEvent(Object.assign(new Event("pageshow"), { persisted: true }));
    await expect.poll(() => a.autosave.tab, { timeout: 3000 }).not.toBe(b.autosave.tab);
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["cached"]);
  });

  it("a fresh tab never takes over the slot of a tab that is open", async () => {
    const p = newProfile();
    const a = await p.open();
    await a.editor.loadScene(scene("open"));
    a.flush();
    const b = await p.open();
    await new Promise((r) => setTimeout(r, ADOPT_AFTER_MS + 200));
    expect(b.autosave.tab).not.toBe(a.autosave.tab);
    await b.editor.loadScene(scene("second"));
    b.flush();
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["open"]);
  });

  it("a reloaded tab whose last scene could not be saved restores the newest scene and says why", async () => {
    const p = newProfile(4000);
    const a = await p.open();
    await a.editor.loadScene(scene("other"));
    a.flush();
    const b = await p.open();
    await b.editor.loadScene(scene("small"));
    b.flush();
    expect(readSlot(p.shared, b.autosave.tab)).not.toBeNull();
    const big: SceneFile = {
      ...scene("x"),
      actions: Array.from({ length: 60 }, (_, i) => scene(`big${i}`, 3 * i).actions[0]!),
    };
    expect(await b.editor.loadScene(big)).toBeNull();
    b.flush();
    expect(b.ui().message?.text).toMatch(/^Autosave failed/);
    expect(readSlot(p.shared, b.autosave.tab)).toBeNull(); // not the older "small" as if it were the latest
    expect(ids(readSlot(p.shared, a.autosave.tab)!.scene)).toEqual(["other"]); // A's work untouched
    const bAgain = await p.open(b.session);
    expect(ids(bAgain.editor.doc)).toEqual(["other"]);
    expect(bAgain.restored?.note).toMatch(/^This tab's last scene could not be autosaved/);
  });
});

describe("autosave keeps the scene a load replaced", () => {
  const reload = (p: ReturnType<typeof profile>, tab: { session: Storage; close(): void }) => {
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
