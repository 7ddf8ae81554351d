/**
 * Test helpers for edits checked by a slow host: an editor with a scene computed to a time, how many
 * copies of an action its host's scene holds, and a promise that resolves once that scene changes
 * (a change's apply was handled and its check runs).
 */
import type { Action, SceneFile } from "../engineTypes";
import { settled, testEditor } from "./harness";

type Harness = ReturnType<typeof testEditor>;

/** A slow test editor (a check lasts many rounds of the host) with `scene` computed to `end`, at `t`. */
export async function slowEditorAt(scene: SceneFile, end: number, t: number): Promise<Harness> {
  const h = testEditor({ slow: true });
  await h.editor.loadScene(scene, { undoable: false });
  await settled(h.client);
  await h.editor.goTo(end);
  await settled(h.client);
  h.editor.ui.setState({ t });
  return h;
}

/** How many actions of the current scene are `a` (same time, type and id). */
export function count(h: Harness, a: Action): number {
  const doc = h.client.getSnapshot().doc!;
  const id = (x: Action) => ("id" in x ? x.id : null);
  return doc.actions.filter((x) => x.time === a.time && x.type === a.type && id(x) === id(a)).length;
}

/** Resolves once the host shows a changed scene (a change's check runs); call before the change. */
export function checking(h: Harness): Promise<void> {
  const rev = h.client.getSnapshot().docRevision;
  return new Promise((resolve) => {
    const stop = h.client.subscribe(() => {
      if (h.client.getSnapshot().docRevision === rev) return;
      stop();
      resolve();
    });
  });
}
