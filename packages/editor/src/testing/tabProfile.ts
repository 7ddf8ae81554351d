/**
 * Test fixtures of the autosave (autosave.ts): small scenes, and a browser profile whose tabs share
 * one localStorage and hear each other's writes (the `storage` event), each tab an editor with its
 * autosave attached, opened fresh or as a reload of a tab (its sessionStorage).
 */
import { TabAutosave } from "../autosave";
import { firstScene, loadFirstScene } from "../boot";
import { EMPTY_SCENE } from "../editor";
import type { SceneFile } from "../engineTypes";
import { settled, testEditor } from "./harness";
import { memoryStorage } from "./memoryStorage";

export const scene = (id: string, x = 0): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id, x, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] }],
});
/** A scene of `n` discs (ids `<id>0`...), to fill the storage. */
export const discs = (id: string, n: number): SceneFile => ({
  ...scene(id),
  actions: Array.from({ length: n }, (_, i) => ({ ...scene(`${id}${i}`, 3 * i).actions[0]! })),
});
export const ids = (s: SceneFile) => s.actions.map((a) => ("id" in a ? a.id : a.type));

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

let current: Profile | null = null;
/** A fresh browser profile (`quota`: of its localStorage), stopped by stopProfile. */
export const newProfile = (quota?: number): Profile => {
  current = profile(quota);
  return current;
};
/** Stops the autosave of every tab of the last profile (call it after each test). */
export const stopProfile = (): void => current?.stop();

export type Profile = ReturnType<typeof profile>;
