/**
 * Autosave slots in localStorage, one per editor tab, so two tabs never overwrite each other's work.
 * A slot is `chapgame.editor.autosave.v2.<tab id>`, its value one line of metadata (`{"savedAt":ms}`,
 * with `"name"`: the file name the scene came from, when it has one: sceneNames.ts) then the scene
 * (format v1). The single slot of earlier versions (`...autosave.v1`, the scene alone)
 * is migrated into the slot of tab "v1" with savedAt 0 (its time is unknown: any newer slot wins).
 * At most MAX_SLOTS slots are kept: the oldest are pruned, never the saving tab's own.
 * Beside each slot, a tab keeps the last scene of its own that a load replaced (Clear, a preset, an
 * opened file...): `chapgame.editor.replaced.v1.<tab id>`, same format, pruned with its slot (and
 * when its tab has no slot), so the scene a replacement took away survives a reload (boot.ts loads
 * it as the step Undo goes back to). The slot always comes first: the replaced scene is written
 * after it, and gives its space up when the slot does not fit (autosave.ts TabAutosave.save).
 * Pure storage access: the caller gives the storage, the tab id and the clock.
 */
import type { SceneFile } from "../engineTypes";
import { parseSceneText } from "./sceneIo";

export const SLOT_PREFIX = "chapgame.editor.autosave.v2.";
/** The one autosave slot of the editor before per-tab slots. */
export const LEGACY_KEY = "chapgame.editor.autosave.v1";
/** The tab id the legacy slot is migrated to. */
export const LEGACY_TAB = "v1";
/** Slots kept at most (tabs that saved; the oldest are pruned, never the current tab's). */
export const MAX_SLOTS = 8;

export interface SlotInfo {
  tab: string;
  key: string;
  /** When the slot was written (ms since the epoch; 0 for a migrated legacy autosave). */
  savedAt: number;
}

export interface Slot extends SlotInfo {
  scene: SceneFile;
  /** The file name the scene came from (what Save file suggests), null when none was stored. */
  name: string | null;
  /** The scene's text as stored (to compare scenes without parsing them again). */
  text: string;
}

export const slotKey = (tab: string): string => SLOT_PREFIX + tab;
/** Where a tab keeps the scene a load replaced. */
export const REPLACED_PREFIX = "chapgame.editor.replaced.v1.";
export const replacedKey = (tab: string): string => REPLACED_PREFIX + tab;

/** The metadata and the scene text of a stored slot value; null when it is not one. */
function split(value: string | null): { savedAt: number; name: string | null; text: string } | null {
  if (value === null) return null;
  const nl = value.indexOf("\n");
  if (nl < 0) return null;
  try {
    const meta = JSON.parse(value.slice(0, nl)) as { savedAt?: unknown; name?: unknown };
    if (typeof meta.savedAt !== "number" || !Number.isFinite(meta.savedAt)) return null;
    const name = typeof meta.name === "string" && meta.name !== "" ? meta.name : null;
    return { savedAt: meta.savedAt, name, text: value.slice(nl + 1) };
  } catch {
    return null;
  }
}

/** savedAt of a slot value (a storage event's newValue, say); null when it is not a slot. */
export function slotSavedAt(value: string | null): number | null {
  return split(value)?.savedAt ?? null;
}

/** The scene text of a slot value; null when it is not a slot. */
export function slotText(value: string | null): string | null {
  return split(value)?.text ?? null;
}

/** Every slot's tab, key and time, newest first (values that are not slots are skipped). */
export function listSlots(storage: Storage): SlotInfo[] {
  const out: SlotInfo[] = [];
  for (const key of slotKeys(storage)) {
    const savedAt = slotSavedAt(storage.getItem(key));
    if (savedAt !== null) out.push({ tab: key.slice(SLOT_PREFIX.length), key, savedAt });
  }
  return out.sort((a, b) => b.savedAt - a.savedAt);
}

function slotKeys(storage: Storage): string[] {
  const keys: string[] = [];
  for (let i = 0; i < storage.length; i++) {
    const key = storage.key(i);
    if (key?.startsWith(SLOT_PREFIX)) keys.push(key);
  }
  return keys;
}

/** The slot of `tab`, or null when there is none or it does not hold a valid scene. */
export function readSlot(storage: Storage, tab: string, key = slotKey(tab)): Slot | null {
  const parts = split(storage.getItem(key));
  if (!parts) return null;
  try {
    const { savedAt, name, text } = parts;
    return { tab, key, savedAt, name, scene: parseSceneText(text), text };
  } catch {
    return null;
  }
}

/**
 * The slot of `tab` when it holds a scene that does not parse (damaged, or written by another
 * version): its text and why it is refused; null when there is no slot or it is valid.
 */
export function unreadableSlot(storage: Storage, tab: string): { text: string; reason: string } | null {
  const parts = split(storage.getItem(slotKey(tab)));
  if (!parts) return null;
  try {
    parseSceneText(parts.text);
    return null;
  } catch (e) {
    return { text: parts.text, reason: e instanceof Error ? e.message : String(e) };
  }
}

/** The most recently saved slot holding a valid scene (other than `except`), or null. */
export function newestSlot(storage: Storage, except: string | null = null): Slot | null {
  for (const s of listSlots(storage)) {
    if (s.tab === except) continue;
    const slot = readSlot(storage, s.tab);
    if (slot) return slot;
  }
  return null;
}

/**
 * Moves the legacy single autosave into the slot of tab LEGACY_TAB (savedAt 0), then removes it.
 * When the storage refuses the copy, the legacy autosave stays where it is (nothing is lost).
 */
export function migrateLegacy(storage: Storage): void {
  const text = storage.getItem(LEGACY_KEY);
  if (text === null) return;
  try {
    storage.setItem(slotKey(LEGACY_TAB), `${JSON.stringify({ savedAt: 0 })}\n${text}`);
  } catch {
    return;
  }
  storage.removeItem(LEGACY_KEY);
}

/** The scene `tab` kept as replaced by a load (replacedKey), or null. */
export const readReplaced = (storage: Storage, tab: string): Slot | null =>
  readSlot(storage, tab, replacedKey(tab));

/**
 * Whether a load that replaced the scene `before` (its text) keeps it as the tab's replaced scene: not
 * an empty scene (nothing to lose), nor `reproducible`, the scene a preset or Clear loaded, unedited
 * (it can be had again): Clear then a preset keeps the work Clear took away, not the empty scene
 * between, and a preset over a preset keeps the work before both.
 */
export function keepsReplaced(
  before: { text: string; empty: boolean },
  reproducible: string | null,
): boolean {
  return !before.empty && before.text !== reproducible;
}

/** Writes the scene a load replaced for `tab` (see writeSlot); null on success, else the failure. */
export function writeReplaced(storage: Storage, tab: string, text: string, savedAt: number): string | null {
  try {
    storage.setItem(replacedKey(tab), `${JSON.stringify({ savedAt })}\n${text}`);
    return null;
  } catch {
    removeReplaced(storage, tab); // an older one would come back as if it were the latest
    return "Autosave could not keep the scene you replaced (the browser's storage is full): Undo brings it back in this tab, but not after a reload.";
  }
}

/** Removes the scene `tab` kept as replaced by a load (nothing when storage is disabled). */
export function removeReplaced(storage: Storage, tab: string): void {
  try {
    storage.removeItem(replacedKey(tab));
  } catch {
    // storage disabled altogether
  }
}

/**
 * Writes `tab`'s slot (`text`: the scene's text, sceneIo.sceneText; `name`: the file name it came
 * from, or null); null on success, else a message for the user. When the scene cannot be stored
 * (storage full or disabled), the tab's older slot is removed: a reload must not bring back an older
 * scene of this tab as if it were the latest. Other tabs' slots are never touched here.
 */
export function writeSlot(
  storage: Storage,
  tab: string,
  text: string,
  savedAt: number,
  name: string | null = null,
): string | null {
  try {
    storage.setItem(
      slotKey(tab),
      `${JSON.stringify(name === null ? { savedAt } : { savedAt, name })}\n${text}`,
    );
    return null;
  } catch {
    try {
      storage.removeItem(slotKey(tab));
    } catch {
      // storage disabled altogether: nothing to remove
    }
    const mb = (text.length / 1e6).toFixed(1);
    return `Autosave failed: the browser's storage refused the scene (${mb} MB of JSON). A reload will not keep it: use Save file.`;
  }
}

/**
 * Keeps at most `max` slots: removes the oldest (with their replaced scenes), never `keep`'s, and
 * removes replaced scenes whose tab has no slot (a slot that could not be written, or one removed
 * by an earlier version): no reload can reach them. Cheap when there are few slots (only the keys
 * are read then).
 */
export function pruneSlots(storage: Storage, keep: string, max = MAX_SLOTS): string[] {
  const keys = slotKeys(storage);
  const orphans = replacedKeys(storage).filter(
    (key) => !keys.includes(slotKey(key.slice(REPLACED_PREFIX.length))),
  );
  for (const key of orphans) storage.removeItem(key);
  if (keys.length <= max) return [];
  const others = keys
    .filter((key) => key !== slotKey(keep))
    // values that are not slots go first
    .map((key) => ({ key, savedAt: slotSavedAt(storage.getItem(key)) ?? Number.NEGATIVE_INFINITY }))
    .sort((a, b) => b.savedAt - a.savedAt);
  const removed = others.slice(max - 1).map((s) => s.key.slice(SLOT_PREFIX.length));
  for (const tab of removed) {
    storage.removeItem(slotKey(tab));
    storage.removeItem(replacedKey(tab));
  }
  return removed;
}

function replacedKeys(storage: Storage): string[] {
  const keys: string[] = [];
  for (let i = 0; i < storage.length; i++) {
    const key = storage.key(i);
    if (key?.startsWith(REPLACED_PREFIX)) keys.push(key);
  }
  return keys;
}
