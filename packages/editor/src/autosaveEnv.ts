/**
 * What the autosave (autosave.ts) needs from the browser, as one object so that tests give their
 * own: localStorage (the slots, shared by the tabs), sessionStorage (this tab's id), a clock, fresh
 * tab ids, and the BroadcastChannel the tabs say hello on (tabPresence.ts; null without one).
 */
import type { TabChannel } from "./tabPresence";

export interface AutosaveEnv {
  local: Storage;
  session: Storage;
  now(): number;
  newTabId(): string;
  channel: TabChannel | null;
}

export function browserAutosaveEnv(): AutosaveEnv {
  return {
    local: window.localStorage,
    session: window.sessionStorage,
    now: () => Date.now(),
    newTabId: () =>
      typeof crypto.randomUUID === "function"
        ? crypto.randomUUID()
        : `${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`,
    channel:
      typeof BroadcastChannel === "undefined"
        ? null
        : (new BroadcastChannel("chapgame.editor.tabs") as unknown as TabChannel),
  };
}
