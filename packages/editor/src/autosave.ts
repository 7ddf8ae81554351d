/**
 * Autosave per tab (slots in doc/autosaveSlots.ts). Each tab has an id in sessionStorage (it survives
 * a reload of that tab, and only that tab) and saves into its own slot 300 ms after each scene change
 * and when the page goes. A reloaded tab restores its own slot; a fresh tab (or one whose slot is
 * gone) restores the most recently saved slot of any tab. When another tab saves newer work, this tab
 * shows a notice (ui.newerWork) with a way to open it (newerWork.ts); Dismiss mutes that tab until
 * this one reloads. Nothing is lost: a slot removed by another tab's pruning is written again at
 * once, and a tab duplicated by the browser (which copies sessionStorage, so the id too) takes a new
 * id on start (tabPresence.ts). A fresh tab that restored the slot of a tab no longer open takes that
 * slot over. The scene a load replaced (Clear, a preset, an opened scene) is written beside the slot
 * (which one: keptReplacement.ts). The browser is reached through an AutosaveEnv (autosaveEnv.ts). */

import type { AutosaveEnv } from "./autosaveEnv";
import {
  migrateLegacy,
  newestSlot,
  pruneSlots,
  readReplaced,
  readSlot,
  removeReplaced,
  replacedKey,
  type Slot,
  slotKey,
  slotSavedAt,
  slotText,
  unreadableSlot,
  writeReplaced,
  writeSlot,
} from "./doc/autosaveSlots";
import { sceneText } from "./doc/sceneIo";
import type { Editor } from "./editor";
import type { SceneFile } from "./engineTypes";
import { KeptReplacement } from "./keptReplacement";
import { clockTime } from "./newerWork";
import type { Replacement } from "./replacementSteps";
import { TabPresence } from "./tabPresence";

/** Milliseconds of quiet after a scene change before it is autosaved. */
export const AUTOSAVE_DELAY_MS = 300;
/** sessionStorage: this tab's id. */
export const TAB_KEY = "chapgame.editor.tab";
/**
 * Milliseconds after start when a fresh tab that restored the slot of a tab no longer open takes
 * that slot over (the open tabs have answered by then), so closing and opening the editor does not
 * pile up copies of one scene.
 */
export const ADOPT_AFTER_MS = 500;
/** sessionStorage: set while this tab's last scene could not be saved. */
const LOST_KEY = "chapgame.editor.tab.lost";

export class TabAutosave {
  tab: string;
  /** True when this tab had an id already (a reload), false for a fresh tab. */
  readonly reloaded: boolean;
  /** The scene text this tab last saved or restored (another tab saving the same is no news). */
  private lastText: string | null = null;
  private ownSavedAt = Number.NEGATIVE_INFINITY;
  private readonly muted = new Set<string>();
  /** The slot of another tab a fresh tab restored (null: none, or its own). */
  private restoredFrom: { tab: string; savedAt: number } | null = null;
  /** The scene a load replaced, kept beside the slot (keptReplacement.ts). */
  private readonly replaced = new KeptReplacement();

  constructor(private readonly env: AutosaveEnv) {
    migrateLegacy(env.local);
    const id = env.session.getItem(TAB_KEY);
    this.reloaded = id !== null;
    this.tab = id ?? env.newTabId();
    if (id === null) env.session.setItem(TAB_KEY, this.tab);
  }

  /**
   * The scene to start with: this tab's own slot on a reload, else the most recently saved slot;
   * `note` says why a reloaded tab did not get its own scene back.
   */
  /** Set by restore(): this tab's own slot when it holds a scene that does not parse (its text and why). */
  unreadable: { text: string; reason: string } | null = null;

  restore(): { slot: Slot; note: string | null; replaced: Slot | null } | null {
    const own = this.reloaded ? readSlot(this.env.local, this.tab) : null;
    // this tab's own slot that no longer parses: kept and announced at start (boot.ts), not dropped
    this.unreadable = this.reloaded && own === null ? unreadableSlot(this.env.local, this.tab) : null;
    const slot = own ?? newestSlot(this.env.local);
    if (!slot) return null;
    this.lastText = slot.text;
    if (own) this.ownSavedAt = own.savedAt;
    else this.restoredFrom = { tab: slot.tab, savedAt: slot.savedAt };
    const lost = this.env.session.getItem(LOST_KEY) !== null;
    const note =
      !own && lost
        ? `This tab's last scene could not be autosaved; restored the scene saved most recently (at ${clockTime(slot.savedAt)}).`
        : null;
    // The scene a load replaced in the tab that saved this slot (unless that load was undone since).
    const replaced = readReplaced(this.env.local, slot.tab);
    return { slot, note, replaced: replaced && replaced.text !== slot.text ? replaced : null };
  }

  /** A load replaced the scene (Editor.replaced): KeptReplacement.replacedBy. */
  replacedBy(replacement: Replacement): void {
    this.replaced.replacedBy(replacement);
  }

  /** The replacements whose step Undo undid: KeptReplacement.undoneNow. */
  undoneNow(undone: ReadonlySet<Replacement>): void {
    this.replaced.undoneNow(undone);
  }

  /** A slot of another tab saved after this tab's own (at start), holding a different scene. */
  newerOther(): Slot | null {
    const other = newestSlot(this.env.local, this.tab);
    if (!other || other.savedAt <= this.ownSavedAt || other.text === this.lastText) return null;
    return other;
  }

  /**
   * Writes this tab's slot and prunes old slots (`prune` false: writing back a slot another tab
   * pruned, which must not prune in turn, or tabs would prune each other for ever); null on success,
   * else a message for the user.
   */
  save(scene: SceneFile, prune = true, name: string | null = null): string | null {
    const now = this.env.now();
    const text = sceneText(scene);
    // The current scene first: the replaced scene beside it is written only after, and gives its
    // space up when the slot does not fit (else near the quota an older scene would stay stored
    // and the current one be lost).
    let failed = writeSlot(this.env.local, this.tab, text, now, name);
    if (failed !== null) {
      // tried again after it (written again below, or with the next save that fits, if it fits too)
      if (this.replaced.text !== null) this.replaced.pending = true;
      if (this.env.local.getItem(replacedKey(this.tab)) !== null) {
        removeReplaced(this.env.local, this.tab);
        failed = writeSlot(this.env.local, this.tab, text, now, name);
      }
    }
    if (failed !== null) {
      this.env.session.setItem(LOST_KEY, "1");
      return failed;
    }
    this.env.session.removeItem(LOST_KEY);
    this.ownSavedAt = now;
    this.lastText = text;
    let replacedFailed: string | null = null;
    if (this.replaced.pending || (!prune && this.replaced.text !== null)) {
      if (this.replaced.text === null) removeReplaced(this.env.local, this.tab);
      else replacedFailed = writeReplaced(this.env.local, this.tab, this.replaced.text, now);
      this.replaced.pending = false;
    }
    if (prune) pruneSlots(this.env.local, this.tab);
    return replacedFailed;
  }

  /**
   * Saves after every scene change of `editor` (AUTOSAVE_DELAY_MS of quiet) and when the page goes,
   * listens to other tabs' saves, and shows the newer-work notice. Returns a function that stops.
   */
  attach(editor: Editor, win: Window): () => void {
    const { client, ui } = editor;
    // The scene last written: the confirmed one (Editor.confirmedDoc), never a change whose later
    // actions are still being checked; its answer (confirmed or taken back) is heard below.
    let savedDoc = editor.confirmedDoc();
    // The file name written with it (sceneNames.ts): saving under another name writes the slot again.
    let savedName = editor.names.name;
    let timer: ReturnType<typeof setTimeout> | null = null;
    let autosaveFailed = false;
    /** `force`: write even when the scene did not change (the slot was pruned, or the id changed). */
    const save = (force = false) => {
      if (timer !== null) clearTimeout(timer);
      timer = null;
      const doc = editor.confirmedDoc();
      const name = editor.names.name;
      if (doc === savedDoc && name === savedName && !force && !this.replaced.pending) return;
      savedDoc = doc;
      savedName = name;
      const failed = doc ? this.save(doc, !force, name) : null;
      if (failed !== null && !autosaveFailed) ui.setState({ message: { text: failed, tone: "error" } });
      autosaveFailed = failed !== null; // said once, until autosave works again
    };
    // A load that replaced the scene before autosave started (a shared link over the autosave, the
    // restored scene over the one it replaced) counts as well.
    const replaced = editor.replaced.getState();
    if (replaced.last) this.replacedBy(replaced.last);
    this.undoneNow(replaced.undone);
    const unsubReplaced = editor.replaced.subscribe((s, p) => {
      if (s.last && s.last !== p.last) this.replacedBy(s.last);
      if (s.undone !== p.undone) this.undoneNow(s.undone);
    });
    const changed = () => {
      if ((editor.confirmedDoc() === savedDoc && editor.names.name === savedName) || timer !== null) return;
      timer = setTimeout(save, AUTOSAVE_DELAY_MS);
    };
    const unsubClient = client.subscribe(changed);
    const unsubConfirmed = editor.unconfirmedStore.subscribe(changed);
    const unsubName = editor.names.current.subscribe(changed);
    // A reload or a closed tab within the quiet delay of an edit keeps that edit.
    const onHide = () => save();
    win.addEventListener("pagehide", onHide);

    // Dismissing the notice (or opening the work) mutes that tab.
    const unsubUi = ui.subscribe((s, p) => {
      if (p.newerWork && s.newerWork === null) this.muted.add(p.newerWork.tab);
    });
    const onStorage = (e: StorageEvent) => {
      if (e.storageArea !== null && e.storageArea !== this.env.local) return;
      if (e.key === null) return;
      const own = slotKey(this.tab);
      if (e.key === own) {
        // another tab pruned this tab's slot (and the replaced scene beside it): write them again
        if (e.newValue === null) save(true);
        return;
      }
      if (!e.key.startsWith(slotKey(""))) return;
      const tab = e.key.slice(slotKey("").length);
      const shown = ui.getState().newerWork;
      const savedAt = slotSavedAt(e.newValue);
      if (savedAt === null) {
        if (shown?.tab === tab) ui.setState({ newerWork: null }); // gone: nothing to open
        return;
      }
      if (this.muted.has(tab) || savedAt <= this.ownSavedAt || slotText(e.newValue) === this.lastText) return;
      ui.setState({ newerWork: { tab, savedAt } });
    };
    win.addEventListener("storage", onStorage);

    const channel = this.env.channel;
    const presence =
      channel &&
      new TabPresence(
        channel,
        () => this.tab,
        () => {
          // a duplicated tab: its scene goes to a slot of its own
          this.tab = this.env.newTabId();
          this.env.session.setItem(TAB_KEY, this.tab);
          save(true);
        },
      );
    const onBye = () => presence?.bye();
    win.addEventListener("pagehide", onBye);
    // Back from the back-forward cache: another tab may have taken over this slot meanwhile.
    const onShow = (e: Event) => {
      if ((e as PageTransitionEvent).persisted) presence?.hello();
    };
    win.addEventListener("pageshow", onShow);
    const adopt = setTimeout(() => {
      const from = this.restoredFrom;
      if (!presence || !from || presence.live.has(from.tab) || this.ownSavedAt > Number.NEGATIVE_INFINITY)
        return;
      // The restored scene's tab is closed: this tab carries on in its slot (one copy, not two).
      this.tab = from.tab;
      this.ownSavedAt = from.savedAt;
      this.env.session.setItem(TAB_KEY, from.tab);
      this.restoredFrom = null;
      presence.hello(); // two fresh tabs adopting the same slot: both take new ids
    }, ADOPT_AFTER_MS);
    return () => {
      if (timer !== null) clearTimeout(timer);
      clearTimeout(adopt);
      unsubClient();
      unsubConfirmed();
      unsubName();
      unsubReplaced();
      unsubUi();
      win.removeEventListener("pagehide", onHide);
      win.removeEventListener("pagehide", onBye);
      win.removeEventListener("pageshow", onShow);
      win.removeEventListener("storage", onStorage);
      presence?.close();
    };
  }
}
