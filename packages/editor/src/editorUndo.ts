/**
 * EditorUndo: Undo and Redo of an Editor (editor.ts), over its EditorSession (and EditorRewrites,
 * editorRewrites.ts). Undo undoes the last
 * change the user had asked for when they pressed it, and Redo redoes the last change Undo took
 * (doc/undoIntents.ts): an Undo pressed while that change is still queued or being checked is bound
 * to it. During the check of its later actions the change is taken back at once (as Cancel does)
 * and nothing else is undone, if it is the last change asked (sceneChanges.ts: an Undo bound to a
 * change with another queued behind it undoes it at its turn); a change the check refuses is not
 * there to undo, so an Undo bound to it undoes nothing (it once undid the edit before it). A change
 * taken back so goes to Redo, which brings it back checked again: a later action may refuse it then
 * (it leaves Redo), while a check cancelled or cut short by an engine restart leaves it in Redo.
 * Like any change made it cleared Redo first (EditorSession.tookBack), so Redo then holds it alone.
 * Each says what it did ("Undone: give velocity to "a" at t = 4 s."). The Undo of a Delete selects
 * the object again, and its Redo selects nothing (doc/stepSelection.ts).
 */

import { summarizeEdit } from "./doc/editSummary";
import { type History, redo, undo } from "./doc/history";
import { differsInMetaAlone } from "./doc/sceneTitle";
import { selectionAfterStep } from "./doc/stepSelection";
import { redoAsked, redoTurn, type Ticket, undoAsked, undoTurn } from "./doc/undoIntents";
import { EditorRewrites } from "./editorRewrites";
import type { SceneFile } from "./engineTypes";

export class EditorUndo extends EditorRewrites {
  /** Scenes in Redo whose later actions were never checked (changes an Undo took back during it). */
  private readonly unchecked = new WeakSet<SceneFile>();

  /** Undoes the last change asked for and says which it was. */
  async undo(): Promise<void> {
    const { intents, ticket } = undoAsked(this.intents.getState());
    this.intents.setState(intents);
    // The last change asked is being applied or checked: take it back now rather than wait for the check.
    this.takeBackIfUndone(ticket);
    const loaded = await this.serial(() => this.undoNow(ticket));
    if (loaded) await this.afterReload();
  }

  /** Redoes the last change Undo took and says which it was. */
  async redo(): Promise<void> {
    const { intents, ticket } = redoAsked(this.intents.getState());
    this.intents.setState(intents);
    const loaded = await this.serial(() => this.redoNow(ticket));
    if (loaded) await this.afterReload();
  }

  /** The queued part of undo: whether a scene was loaded. */
  private async undoNow(ticket: Ticket): Promise<boolean> {
    const current = this.doc;
    const drafts = this.drafts.all(); // those open now: a load's step drops them (stepped)
    const h = this.history.getState();
    const turn = undoTurn(ticket);
    if (turn === "nothing") return false; // refused: the message said why, and nothing is undone
    if (turn === "toFuture") {
      // The host already took it back (and brings the old history back): only Redo learns of it.
      const scene = ticket.scene as SceneFile;
      this.unchecked.add(scene);
      this.history.setState({ past: h.past, future: [scene, ...h.future] });
      ticket.fate = "done";
      this.info(
        `Undone: ${summarizeEdit(current, scene)} (taken back while the actions after it were being checked).`,
      );
      return false;
    }
    const u = undo(h, current);
    if (u === null) this.info("Nothing to undo.");
    const loaded =
      u !== null &&
      (await this.restore(
        u.scene,
        u.history,
        this.loadStepSummary(u.scene, true) ?? `Undone: ${summarizeEdit(u.scene, current)}.`,
      ));
    if (loaded) this.stepped(true, u.scene, u.history, drafts);
    if (!loaded) ticket.fate = "refused"; // nothing undone: a Redo bound to it has nothing to redo
    return loaded;
  }

  /** The queued part of redo: whether a scene was loaded. */
  private async redoNow(ticket: Ticket | null): Promise<boolean> {
    if (ticket === null) {
      // (the last message, "Redone: …", stayed up as if the key had done it again: review)
      this.info("Nothing to redo.");
      return false;
    }
    if (redoTurn(ticket) === "nothing") return false;
    const current = this.doc;
    const drafts = this.drafts.all(); // those open now: a load's step drops them (stepped)
    const r = redo(this.history.getState(), current);
    if (r === null) this.info("Nothing to redo.");
    const loaded =
      r !== null &&
      (await this.restore(
        r.scene,
        r.history,
        this.loadStepSummary(r.scene, false) ?? `Redone: ${summarizeEdit(current, r.scene)}.`,
      ));
    if (loaded) this.stepped(false, r.scene, r.history, drafts);
    if (!loaded) ticket.fate = "refused"; // nothing redone: an Undo bound to it has nothing to undo
    return loaded;
  }

  /**
   * The queued part of undo and redo: whether the scene was loaded (then `said` is shown). A scene
   * never checked is checked as a rewrite is; refused by a later action (the refusal names it), it
   * leaves Redo (it cannot be brought back). A check cancelled, or answered "engine restarted",
   * decided nothing: the scene stays in Redo.
   */
  private async restore(scene: SceneFile, history: History, said: string): Promise<boolean> {
    const from = this.doc;
    const check = this.unchecked.has(scene);
    try {
      if (check) this.unconfirmed = this.doc; // what a restart loads meanwhile
      // a step that changed the meta alone (a title) brings it back without recomputing anything
      if (!check && differsInMetaAlone(from, scene)) await this.client.setMeta(scene.meta ?? null);
      else await this.client.load(scene, this.keepTo(), check);
    } catch (e) {
      if (!check || !namesAction(e)) {
        this.fail(e);
        return false;
      }
      const h = this.history.getState();
      this.history.setState({ past: h.past, future: h.future.filter((s) => s !== scene) });
      this.failNaming(e, scene.actions);
      return false;
    } finally {
      this.unconfirmed = null;
    }
    this.unchecked.delete(scene);
    this.history.setState(history);
    this.names.returned(from, scene);
    // the Undo of a Delete selects the object again, its Redo selects nothing (doc/stepSelection.ts)
    this.ui.setState((s) => ({ selection: selectionAfterStep(from, scene, s.selection) }));
    this.info(said);
    return true;
  }
}

/** Whether a refusal names an action (the engine's path `actions[i]`), as a later action refusing a change does. */
function namesAction(e: unknown): boolean {
  return typeof (e as { path?: unknown } | null)?.path === "string";
}
