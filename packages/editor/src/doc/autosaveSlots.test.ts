import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { memoryStorage } from "../testing/memoryStorage";
import {
  LEGACY_KEY,
  LEGACY_TAB,
  listSlots,
  MAX_SLOTS,
  migrateLegacy,
  newestSlot,
  pruneSlots,
  readReplaced,
  readSlot,
  replacedKey,
  slotKey,
  slotSavedAt,
  writeReplaced,
  writeSlot,
} from "./autosaveSlots";
import { sceneText } from "./sceneIo";

const scene = (g: number): SceneFile => ({
  format: "chapgame",
  version: 1,
  g,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "ä/β", x: 1, y: 2, r: 3, m: 4, mu: 0.5, v: [1, -1] }],
});

describe("autosave slots", () => {
  it("a slot round-trips its scene and time; broken slots are skipped, the newest valid one wins", () => {
    const st = memoryStorage();
    expect(writeSlot(st, "a", sceneText(scene(1)), 100)).toBeNull();
    expect(writeSlot(st, "b", sceneText(scene(2)), 300)).toBeNull();
    expect(readSlot(st, "a")).toMatchObject({ tab: "a", savedAt: 100, scene: scene(1) });
    expect(slotSavedAt(st.getItem(slotKey("b")))).toBe(300);
    expect(newestSlot(st)?.tab).toBe("b");
    expect(newestSlot(st, "b")?.tab).toBe("a");
    st.setItem(slotKey("c"), `${JSON.stringify({ savedAt: 500 })}\n{broken`);
    st.setItem(slotKey("d"), "no metadata");
    expect(readSlot(st, "c")).toBeNull();
    expect(newestSlot(st)?.tab).toBe("b"); // c is newer but holds no valid scene
    expect(listSlots(st).map((s) => s.tab)).toEqual(["c", "b", "a"]);
    expect(readSlot(st, "missing")).toBeNull();
  });

  it("the single autosave of earlier versions is migrated (savedAt 0: any newer slot wins) and removed", () => {
    const st = memoryStorage();
    st.setItem(LEGACY_KEY, sceneText(scene(7)));
    migrateLegacy(st);
    expect(st.getItem(LEGACY_KEY)).toBeNull();
    expect(readSlot(st, LEGACY_TAB)).toMatchObject({ savedAt: 0, scene: scene(7) });
    expect(newestSlot(st)?.scene).toEqual(scene(7));
    writeSlot(st, "t", sceneText(scene(8)), 1);
    expect(newestSlot(st)?.tab).toBe("t");
    migrateLegacy(st); // nothing left to migrate: the migrated slot stays
    expect(readSlot(st, LEGACY_TAB)?.scene).toEqual(scene(7));
  });

  it("a legacy autosave the storage cannot copy stays where it is", () => {
    const text = sceneText(scene(7));
    const st = memoryStorage(LEGACY_KEY.length + text.length + 10);
    st.setItem(LEGACY_KEY, text);
    migrateLegacy(st);
    expect(st.getItem(LEGACY_KEY)).toBe(text);
  });

  it(`keeps at most ${MAX_SLOTS} slots: the oldest go first, never the saving tab's own`, () => {
    const st = memoryStorage();
    for (let i = 0; i < MAX_SLOTS; i++) writeSlot(st, `t${i}`, sceneText(scene(i)), 10 + i);
    expect(pruneSlots(st, "t0")).toEqual([]);
    // t0 is the oldest but saving: t1 (the next oldest) goes
    writeSlot(st, "new", sceneText(scene(99)), 1000);
    expect(pruneSlots(st, "t0")).toEqual(["t1"]);
    expect(listSlots(st).length).toBe(MAX_SLOTS);
    expect(readSlot(st, "t0")).not.toBeNull();
    // a value that is not a slot goes before any slot
    st.setItem(slotKey("junk"), "junk");
    expect(pruneSlots(st, "new")).toEqual(["junk"]);
    expect(pruneSlots(st, "new", 3).sort()).toEqual(["t0", "t2", "t3", "t4", "t5"]);
    expect(listSlots(st).map((s) => s.tab)).toEqual(["new", "t7", "t6"]);
  });

  it("a scene too large for the storage removes this tab's older slot (only it) and says so", () => {
    const st = memoryStorage(3000);
    writeSlot(st, "other", sceneText(scene(1)), 1);
    expect(writeSlot(st, "me", sceneText(scene(2)), 2)).toBeNull();
    const huge = sceneText(scene(3)) + " ".repeat(5000);
    expect(writeSlot(st, "me", huge, 3)).toMatch(/^Autosave failed: .* use Save file\.$/);
    expect(readSlot(st, "me")).toBeNull(); // a reload must not bring back the older scene as the latest
    expect(readSlot(st, "other")?.scene).toEqual(scene(1));
  });

  it("a replaced scene whose tab has no slot is pruned (no reload can reach it), with any number of slots", () => {
    const st = memoryStorage();
    writeSlot(st, "a", sceneText(scene(1)), 1);
    writeReplaced(st, "a", sceneText(scene(2)), 1);
    writeReplaced(st, "gone", sceneText(scene(3)), 1);
    writeReplaced(st, "lost", sceneText(scene(4)), 1);
    expect(pruneSlots(st, "a")).toEqual([]);
    expect(st.getItem(replacedKey("gone"))).toBeNull();
    expect(st.getItem(replacedKey("lost"))).toBeNull();
    expect(readReplaced(st, "a")?.scene).toEqual(scene(2));
    expect(readSlot(st, "a")?.scene).toEqual(scene(1));
  });
});
