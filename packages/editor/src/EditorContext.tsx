/** React bindings: the Editor through context, UI-store selectors and the timeline info snapshot. */
import { createContext, useContext, useSyncExternalStore } from "react";
import type { History } from "./doc/history";
import type { Editor } from "./editor";
import type { TimelineInfo } from "./remote/protocol";
import { useStore } from "./store/createStore";
import type { UiState } from "./store/uiStore";

export const EditorContext = createContext<Editor | null>(null);

export function useEditor(): Editor {
  const e = useContext(EditorContext);
  if (!e) throw new Error("useEditor outside <EditorContext.Provider>");
  return e;
}

export function useUi<U>(selector: (s: UiState) => U): U {
  return useStore(useEditor().ui, selector);
}

export function useHistory<U>(selector: (h: History) => U): U {
  return useStore(useEditor().history, selector);
}

/**
 * The count of scenes the current one replaced (EditorSession.sceneSerial): the tables key their rows
 * with it, so a cell's draft never outlives its scene.
 */
export function useSceneSerial(): number {
  return useStore(useEditor().sceneSerial, (s) => s.serial);
}

/** The latest TimelineInfo (re-renders on every timeline change: use in small components only). */
export function useInfo(): TimelineInfo {
  const c = useEditor().client;
  return useSyncExternalStore(c.subscribe, c.getSnapshot, c.getSnapshot);
}

/** A value derived from the TimelineInfo; re-renders only when it changes (Object.is). */
export function useInfoValue<U>(selector: (i: TimelineInfo) => U): U {
  const c = useEditor().client;
  return useSyncExternalStore(
    c.subscribe,
    () => selector(c.getSnapshot()),
    () => selector(c.getSnapshot()),
  );
}
