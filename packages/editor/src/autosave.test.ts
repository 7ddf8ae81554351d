// Autosave per tab: each tab its own slot, restored on its reload; a fresh tab restores the newest;
// another tab's newer work is offered; slots are pruned, written back, taken over and handed on.
import { afterEach, describe, expect, it } from "vitest";
import { ADOPT_AFTER_MS, TAB_KEY } from "./autosave";
import { LEGACY_KEY, listSlots, MAX_SLOTS, readSlot, slotKey } from "./doc/autosaveSlots";
import { sceneText } from "./doc/sceneIo";
import type { SceneFile } from "./engineTypes";
import { openNewerWork } from "./newerWork";
import { settled } from "./testing/harness";
import { memoryStorage } from "./testing/memoryStorage";
import { ids, newProfile, scene, stopProfile } from "./testing/tabProfile";

afterEach(stopProfile);

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

describe("autosave keeps the scene's file name", () => {
  it("a reload suggests the name the scene came from, and a save under another name is kept too", async () => {
    const p = newProfile();
    const a = await p.open();
    // opened over work of its own, which the reload brings back first (Undo's step): the path
    // that once dropped the name
    await a.editor.loadScene(scene("work"));
    a.flush();
    await a.editor.loadScene(scene("opened"), { name: "billiards.chapgame.json" });
    a.flush();
    expect(readSlot(p.shared, a.autosave.tab)?.name).toBe("billiards.chapgame.json");
    const again = await p.open(a.session, true, true); // the tab reloads (as boot.ts starts)
    expect(ids(again.editor.doc)).toEqual(["opened"]);
    expect(again.editor.names.name).toBe("billiards.chapgame.json");
    expect(again.editor.history.getState().past.map(ids)).toEqual([["work"]]);
    // saved under another name (the scene unchanged): the slot is written again with it
    again.editor.names.saved("break-shot.chapgame.json");
    again.flush();
    expect(readSlot(p.shared, a.autosave.tab)?.name).toBe("break-shot.chapgame.json");
    expect((await p.open(a.session, true, true)).editor.names.name).toBe("break-shot.chapgame.json");
    // a scene without a name writes none (a slot of an earlier version has none either)
    const b = await p.open();
    await b.editor.loadScene(scene("nameless"));
    b.flush();
    expect(readSlot(p.shared, b.autosave.tab)?.name).toBeNull();
    expect(p.shared.getItem(slotKey(b.autosave.tab))?.split("\n")[0]).not.toMatch(/name/);
  });
});
