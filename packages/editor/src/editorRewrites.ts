/**
 * EditorRewrites: the changes of the current scene as a whole, over EditorSession (editorSession.ts)
 * and under EditorUndo (editorUndo.ts): its meta (a title), a rewrite of its action list (removing
 * an action, any whole-scene change) and the rename of a body, line or point everywhere. Each is
 * one undo step, queued behind the changes asked before it (sceneChanges.ts), and keeps the time,
 * playback and selection (a rename selects the renamed object); a rewrite or rename computes the
 * history again up to where it reached, a change of meta recomputes nothing. Each resolves to null, or to the message of its refusal, which for a rewrite
 * or rename a later action made invalid names that action (doc/actionRefs.ts).
 */

import { record } from "./doc/history";
import { type ObjectKind, renameObject } from "./doc/rename";
import { EditorSession } from "./editorSession";
import type { SceneFile } from "./engineTypes";

export class EditorRewrites extends EditorSession {
  /**
   * Replaces the scene's meta (free data for tools: its title; undefined: none) by `next` of the
   * scene's when the change's turn comes, as one undo step. Nothing is recomputed (the history does
   * not depend on it: client.setMeta) and the time stays. `then` runs once it is applied, before the
   * next change (the file name a title gives).
   */
  async changeMeta(
    next: (doc: SceneFile) => Record<string, unknown> | undefined,
    then?: () => void,
  ): Promise<string | null> {
    return this.changes.ticketed(async () => {
      const before = this.doc;
      try {
        await this.client.setMeta(next(before) ?? null);
      } catch (e) {
        return this.fail(e);
      }
      this.history.setState(record(this.history.getState(), before));
      this.names.left(before);
      then?.();
      return null;
    });
  }

  /**
   * Replaces the action list as one undo step (renames, removing an action, other whole-scene
   * rewrites). `scene` may be a function of the current scene, called when the change's turn comes
   * (after the changes queued before it); one that throws refuses the rewrite with its message.
   */
  async rewrite(scene: SceneFile | ((doc: SceneFile) => SceneFile)): Promise<string | null> {
    const options = { fit: false, keepTime: true };
    const loaded = await this.changes.ticketed(async (ticket) => {
      let next: SceneFile;
      try {
        next = typeof scene === "function" ? scene(this.doc) : scene;
      } catch (e) {
        return this.fail(e);
      }
      return this.loadNow(next, options, true, ticket);
    });
    return this.afterLoad(loaded, options);
  }

  /** Renames a body, line or point in the whole action list (one undo step). */
  async rename(kind: ObjectKind, from: string, to: string): Promise<string | null> {
    const options = { fit: false, keepTime: true };
    const loaded = await this.changes.ticketed(async (ticket) => {
      let scene: SceneFile;
      try {
        scene = renameObject(this.doc, kind, from, to);
      } catch (e) {
        return this.fail(e);
      }
      return this.loadNow(scene, options, true, ticket);
    });
    if (loaded === null) this.ui.setState({ selection: { kind, id: to } });
    return this.afterLoad(loaded, options);
  }
}
