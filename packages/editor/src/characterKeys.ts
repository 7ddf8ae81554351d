/**
 * Whether the one-character shortcuts (letters, digits, + − ?) run, kept across reloads in
 * localStorage: a speech-input user who turns them off (WCAG 2.1.4, Character Key Shortcuts) must
 * not find them on again at the next visit. Storage that cannot be read or written (a private
 * window, a full quota) leaves the default, on, and the switch still works for the session.
 */

/** The page's localStorage, or undefined where reading it throws (storage blocked). */
export function pageStorage(): Storage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}

/** localStorage key: "off" when the one-character shortcuts are turned off. */
export const CHARACTER_KEYS_KEY = "chapgame.characterKeys";

export function loadCharacterKeys(storage: Storage | undefined): boolean {
  try {
    return storage?.getItem(CHARACTER_KEYS_KEY) !== "off";
  } catch {
    return true;
  }
}

export function saveCharacterKeys(storage: Storage | undefined, on: boolean): void {
  try {
    if (on) storage?.removeItem(CHARACTER_KEYS_KEY);
    else storage?.setItem(CHARACTER_KEYS_KEY, "off");
  } catch {
    // kept for this session only
  }
}
