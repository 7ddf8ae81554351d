// The time kept across a reload: written when the page goes, restored only for the same scene
// (computed up to it when past the horizon), and nothing kept or restored when storage fails.
import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { settled, testEditor } from "./testing/harness";
import { memoryStorage } from "./testing/memoryStorage";
import {
  keepTimeOnLeave,
  keptCalc,
  keptTime,
  restoreKeptCalc,
  restoreKeptTime,
  sceneFingerprint,
  TIME_KEY,
} from "./timeKeep";

async function cradleAt(t: number) {
  const h = testEditor();
  await h.editor.loadScene(newtonsCradle(), { undoable: false });
  await settled(h.client);
  h.editor.ui.setState({ t });
  return h;
}

/** A tab's page going away: its pagehide listeners run. */
function leave(win: EventTarget): void {
  win.dispatchEvent(new Event("pagehide"));
}

describe("timeKeep", () => {
  it("a reload of the same scene goes back to the time the tab was at", async () => {
    const session = memoryStorage();
    const win = new EventTarget() as unknown as Window;
    const before = await cradleAt(3.25);
    const stop = keepTimeOnLeave(before.editor, win, session);
    leave(win);
    stop();
    const after = testEditor();
    await after.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(after.client);
    expect(after.editor.ui.getState().t).toBe(0);
    await restoreKeptTime(after.editor, session);
    expect(after.editor.ui.getState().t).toBe(3.25);
  });

  it("a time past the horizon is computed first, then shown", async () => {
    const session = memoryStorage();
    const win = new EventTarget() as unknown as Window;
    const before = await cradleAt(0);
    await before.editor.goTo(42);
    await settled(before.client);
    keepTimeOnLeave(before.editor, win, session);
    leave(win);
    const after = testEditor();
    await after.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(after.client);
    expect(after.client.getSnapshot().horizon).toBeLessThan(42);
    await restoreKeptTime(after.editor, session);
    await settled(after.client);
    expect(after.editor.ui.getState().t).toBe(42);
    expect(after.client.getSnapshot().horizon).toBeGreaterThanOrEqual(42);
  });

  it("another scene starts at 0: the kept time belongs to the scene it was taken in", async () => {
    const session = memoryStorage();
    const cradle = newtonsCradle();
    session.setItem(TIME_KEY, JSON.stringify({ t: 5, scene: sceneFingerprint(cradle) }));
    expect(keptTime(session, cradle)).toBe(5);
    const moved = { ...cradle, g: cradle.g + 1 };
    expect(keptTime(session, moved)).toBeNull();
  });

  it("a broken or missing entry, or storage that throws, keeps and restores nothing, without an error", async () => {
    const cradle = newtonsCradle();
    const session = memoryStorage();
    expect(keptTime(session, cradle)).toBeNull();
    session.setItem(TIME_KEY, "{not json");
    expect(keptTime(session, cradle)).toBeNull();
    session.setItem(TIME_KEY, JSON.stringify({ t: "5", scene: sceneFingerprint(cradle) }));
    expect(keptTime(session, cradle)).toBeNull();
    const throwing = {
      getItem() {
        throw new Error("denied");
      },
      setItem() {
        throw new Error("denied");
      },
    } as unknown as Storage;
    expect(keptTime(throwing, cradle)).toBeNull();
    const h = await cradleAt(2);
    const win = new EventTarget() as unknown as Window;
    keepTimeOnLeave(h.editor, win, throwing);
    expect(() => leave(win)).not.toThrow();
    expect(h.editor.ui.getState().message).toBeNull();
  });

  it("the Calculation settings come back whatever the scene; broken ones are ignored", async () => {
    const session = memoryStorage();
    const win = new EventTarget() as unknown as Window;
    const before = await cradleAt(1);
    const calc = { useTime: true, seconds: 300, useEvents: true, events: 5000, autoExtend: false };
    before.editor.ui.setState({ calc });
    keepTimeOnLeave(before.editor, win, session);
    leave(win);
    const after = testEditor();
    restoreKeptCalc(after.editor, session);
    expect(after.editor.ui.getState().calc).toEqual(calc);
    const raw = JSON.parse(session.getItem(TIME_KEY)!);
    session.setItem(TIME_KEY, JSON.stringify({ ...raw, calc: { ...calc, seconds: -1 } }));
    expect(keptCalc(session)).toBeNull();
    session.setItem(TIME_KEY, "[");
    expect(keptCalc(session)).toBeNull();
  });
});
