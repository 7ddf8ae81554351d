/**
 * Keeps the UI store's selection pointing at an object of the scene: whenever the scene (the
 * document) changes, a selection whose body, line or point no longer exists in it is dropped (after
 * undoing the Add body that selected it, Delete would otherwise name a body that is gone).
 * An object exists when the scene adds it at some time, even if it is removed later or added after
 * the current time.
 */
import type { SceneFile } from "../engineTypes";
import type { Selection, UiStore } from "./uiStore";

/** What the guard watches: the TimelineClient's snapshot (doc and its revision) and its changes. */
export interface SceneSource {
  getSnapshot(): { doc: SceneFile | null; docRevision: number };
  subscribe(listener: () => void): () => void;
}

const ADDED_BY = { body: "addBody", line: "addLine", point: "addPoint" } as const;

/** Whether `doc` has the selected object (some action adds a body, line or point with that id). */
export function selectionExists(doc: SceneFile, sel: NonNullable<Selection>): boolean {
  const type = ADDED_BY[sel.kind];
  return doc.actions.some((a) => a.type === type && a.id === sel.id);
}

/** Drops the selection of `ui` when a change of the scene of `source` removes its object; returns the unsubscribe. */
export function dropStaleSelection(ui: UiStore, source: SceneSource): () => void {
  let revision = source.getSnapshot().docRevision;
  return source.subscribe(() => {
    const info = source.getSnapshot();
    if (info.docRevision === revision) return;
    revision = info.docRevision;
    const sel = ui.getState().selection;
    if (sel !== null && info.doc !== null && !selectionExists(info.doc, sel))
      ui.setState({ selection: null });
  });
}
