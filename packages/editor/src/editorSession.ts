/**
 * EditorSession: the base of EditorRewrites, EditorUndo and so of Editor (editor.ts) that owns the
 * scene session. Over EditorCompute (editorCompute.ts: the TimelineClient, the UI store (time,
 * speed, selection...), messages, computing ahead) it holds the undo history (whole scenes; only
 * edits are recorded: a drag ends in one action, scrubbing, speed and selection are never
 * recorded). It loads scenes, applies edits as undo steps, undoes and redoes them (editorUndo.ts),
 * computes ahead after each (Calculation settings) and restarts a host that stopped answering.
 * Methods that can fail resolve to the engine's message (null on success) and show it in the UI.
 * Changes of the scene (loads, edits, undo, redo) run strictly one after another; each undoable
 * change gets a ticket when asked (doc/undoIntents.ts), so an Undo asked while it is still queued
 * or checked is bound to it (sceneChanges.ts). An edit refused because a later action would become
 * invalid (the engine's path `actions[i]`) also says which action that is (doc/actionRefs.ts). The
 * changes of the scene as a whole that keep the time (its meta, a rewrite of its actions, a rename)
 * are editorRewrites.ts's. A load that replaces the scene (undoable, not keeping the time: Clear, a
 * preset, an opened scene) is published in `replaced` (the scene before and the one loaded), so
 * autosave can keep the scene taken away, and so is an Undo or Redo of its step (autosave then
 * keeps that scene only while it is done; the steps of such loads: replacementSteps.ts).
 */

import { EMPTY_HISTORY, type History, record, takenBack } from "./doc/history";
import type { Intents, Ticket } from "./doc/undoIntents";
import { EditorCompute } from "./editorCompute";
import type { Action, SceneFile } from "./engineTypes";
import { droppedNote, type OpenDraft, OpenDrafts } from "./openDrafts";
import { inApplyingOrder } from "./remote/actionIndices";
import { type Port, UNDONE_DURING_CHECK } from "./remote/protocol";
import { type Replaced, ReplacementSteps } from "./replacementSteps";
import { SceneChanges } from "./sceneChanges";
import { SceneNames } from "./sceneNames";
import { createStore, type Store } from "./store/createStore";

export { shown } from "./editorCompute";

/** How a scene is loaded (loadScene). */
export interface LoadOptions {
  /** false: not an undo step (start-up). */
  undoable?: boolean;
  /** false: the view is not fitted to the scene. */
  fit?: boolean;
  /** A rewrite of the current scene: the time, playback, selection and zoom stay. */
  keepTime?: boolean;
  /** The scene loaded can be had again as it is (a preset, Clear): see Replacement. */
  reproducible?: boolean;
  /**
   * The file name the loaded scene came from (an opened file's, a preset's), which Save file
   * suggests (sceneNames.ts); a load that replaces the scene without one leaves it with none. A
   * rewrite of the current scene (keepTime) keeps the current name.
   */
  name?: string | null;
  /** `name` is a preset's, not one the author chose: a title set later names the file (sceneNames.ts). */
  preset?: boolean;
}

export class EditorSession extends EditorCompute {
  readonly history: Store<History> = createStore<History>(EMPTY_HISTORY);
  /** The queue of scene changes and the tickets and take-backs of Undo (sceneChanges.ts). */
  protected readonly changes = new SceneChanges(this.client);
  /** Undo and Redo as the user asked them, over `history`, while changes are queued (undoIntents.ts). */
  readonly intents: Store<Intents> = this.changes.intents;
  /** The undo steps of loads that replaced the scene (replacementSteps.ts). */
  private readonly replacements = new ReplacementSteps();
  /**
   * The last load that replaced the scene (the scene it took away and the one it loaded), and the
   * recent ones whose undo step is undone now (Undo went back past them; Redo may bring them back).
   */
  readonly replaced: Store<Replaced> = this.replacements.replaced;
  /**
   * Counts the scenes the current one replaced: a load that does not keep the time (Clear, a preset,
   * a file, a paste, a link, start-up) and an Undo or Redo of such a load's step. The tables key
   * their rows with it, so that a cell's draft never outlives its scene: typed for an object of the
   * scene before, it would apply to whatever has its id in the new one.
   */
  readonly sceneSerial: Store<{ serial: number }> = createStore<{ serial: number }>({ serial: 0 });
  /** The cells' drafts not applied (openDrafts.ts): what a step that takes them away says it dropped. */
  readonly drafts = new OpenDrafts();
  /**
   * What the last scene replaced said of the drafts it dropped, while the message bar may still show
   * it alone: the message the load's caller gives next (info) says it too.
   */
  private dropNote: string | null = null;
  /** The file name the current scene came from, which Save file suggests (sceneNames.ts). */
  readonly names = new SceneNames();
  /** Makes a fresh host (a new Web Worker) for restartEngine; null where none can be made. */
  portFactory: (() => Port) | null = null;
  /**
   * The scene before a change the host has not answered yet (an edit or a rewrite whose later
   * actions it is still checking; its doc already shows the change), null when none is: what a
   * restarted engine loads, since the change is answered "engine restarted" and never recorded, and
   * what the autosave keeps meanwhile (confirmedDoc). A store, so the autosave hears the answer.
   */
  readonly unconfirmedStore: Store<{ before: SceneFile | null }> = createStore<{ before: SceneFile | null }>({
    before: null,
  });
  protected get unconfirmed(): SceneFile | null {
    return this.unconfirmedStore.getState().before;
  }
  protected set unconfirmed(before: SceneFile | null) {
    if (before !== this.unconfirmedStore.getState().before) this.unconfirmedStore.setState({ before });
  }

  /**
   * The scene as far as it is confirmed: the current one, or while a change is being checked the
   * scene before it (a reload then must not restore a scene the check may still refuse: review,
   * session 19, a refused autosave replaced the user's 5,000 discs by the default scene).
   */
  confirmedDoc(): SceneFile | null {
    return this.unconfirmed ?? this.client.getSnapshot().doc;
  }

  /** After Undo (`undo`) or Redo restored `scene` with the history `h`: ReplacementSteps.stepped. */
  protected stepped(undo: boolean, scene: SceneFile, h: History, drafts: readonly OpenDraft[]): void {
    if (!this.replacements.stepped(undo, scene, h)) return;
    // said after the step's own message ("Undone: …"), given already
    const note = this.nextScene(drafts);
    const said = this.ui.getState().message;
    if (note !== "")
      this.ui.setState({ message: { text: said ? `${said.text} ${note}` : note, tone: "info" } });
    this.dropNote = null;
  }

  /**
   * The scene was replaced by another (sceneSerial): the tables' rows, keyed by it, go with every
   * draft; returns what to say of `drafts`, those open when the step began (openDrafts.ts
   * droppedNote: "" when there were none). Read then: the refused action's row goes as soon as the
   * load starts, its cells and their drafts with it.
   */
  private nextScene(drafts: readonly OpenDraft[]): string {
    const note = droppedNote(drafts);
    this.dropNote = note === "" ? null : note;
    this.sceneSerial.setState((s) => ({ serial: s.serial + 1 }));
    return note;
  }

  /** Shows `text`, and the drafts the last load dropped when the bar still shows that alone. */
  override info(text: string): void {
    const note = this.dropNote;
    this.dropNote = null;
    super.info(note !== null && this.ui.getState().message?.text === note ? `${text} ${note}` : text);
  }

  /** What Undo or Redo says when it goes to `scene` if a load replaced it (ReplacementSteps.summary), else null. */
  protected loadStepSummary(scene: SceneFile, undo: boolean): string | null {
    return this.replacements.summary(scene, undo);
  }

  /** Runs `change` once the scene changes queued before it are done (SceneChanges.serial). */
  protected serial<T>(change: () => Promise<T>): Promise<T> {
    return this.changes.serial(change);
  }

  /** Takes back the running change of `ticket` an Undo is bound to (SceneChanges.takeBackIfUndone). */
  protected takeBackIfUndone(ticket: Ticket): void {
    this.changes.takeBackIfUndone(ticket);
  }

  /**
   * After the change of `ticket` was refused: whether an Undo took it back during its check
   * (SceneChanges.tookBack). Such a change was made, so it clears Redo as recording it would have
   * (history.ts takenBack); its Undo then puts it first in Redo.
   */
  private async tookBack(ticket: Ticket): Promise<boolean> {
    if (!(await this.changes.tookBack(ticket))) return false;
    this.history.setState(takenBack(this.history.getState()));
    return true;
  }

  /** Loads a scene (preset, paste, file, URL). Invalid scenes are refused and the current one kept. */
  async loadScene(scene: SceneFile, options: LoadOptions = {}): Promise<string | null> {
    const loaded =
      options.undoable === false
        ? await this.serial(() => this.loadNow(scene, options))
        : await this.changes.ticketed((ticket) => this.loadNow(scene, options, false, ticket));
    return this.afterLoad(loaded, options);
  }

  /**
   * The queued part of loadScene: the load and its undo step; null, or the message. `naming`: a
   * refusal says which action the engine's `actions[i]` is (for rewrites of the current scene, whose
   * actions are in the Event log; not for a file, a paste or a preset).
   */
  protected async loadNow(
    scene: SceneFile,
    options: LoadOptions,
    naming = false,
    ticket: Ticket | null = null,
  ): Promise<string | null> {
    const before = this.doc;
    const drafts = this.drafts.all();
    try {
      // A rewrite of the current scene is checked up to where its history reached before the
      // reply (a removed action could leave a later one invalid); until then it is unconfirmed.
      if (naming) this.unconfirmed = before;
      const loaded = this.client.load(scene, options.keepTime ? this.keepTo() : undefined, naming);
      if (ticket !== null) this.takeBackIfUndone(ticket);
      await loaded;
    } catch (e) {
      if (ticket !== null && (await this.tookBack(ticket))) return UNDONE_DURING_CHECK;
      // The engine names actions by their index in the list it was given (the host gives it the
      // scene's in applying order).
      const given = inApplyingOrder(scene).actions;
      return naming ? this.failNaming(e, given) : this.failNamed(e, given);
    } finally {
      this.unconfirmed = null;
    }
    if (options.undoable !== false) this.history.setState(record(this.history.getState(), before));
    this.names.left(before);
    if (!options.keepTime) this.names.loaded(options.name ?? null, options.preset === true);
    const dropped = options.keepTime ? "" : this.nextScene(drafts);
    if (options.undoable !== false && !options.keepTime)
      this.replacements.recorded({ before, loaded: this.doc, reproducible: options.reproducible === true });
    this.ui.setState((s) => ({
      t: options.keepTime ? s.t : 0,
      playing: options.keepTime ? s.playing : false,
      selection: options.keepTime ? s.selection : null,
      // an entry of the other scene's log (Event details said an edit had removed it: review)
      selectedEvent: options.keepTime ? s.selectedEvent : null,
      highlight: [],
      // the drafts the load took away, if any (the caller's message then says it too: info)
      message: dropped === "" ? null : { text: dropped, tone: "info" },
      fitRequest: options.fit === false ? s.fitRequest : s.fitRequest + 1,
      // the Time slider's zoom was a window of the other scene's history
      timeWindow: options.keepTime ? s.timeWindow : null,
    }));
    return null;
  }

  /** The rest of loadScene, not queued: computing ahead. */
  protected async afterLoad(loaded: string | null, options: { keepTime?: boolean }): Promise<string | null> {
    if (loaded !== null) return loaded;
    if (options.keepTime) await this.afterReload();
    else await this.computeAhead();
    return null;
  }

  /**
   * Applies edits as one undo step; on error nothing changes and the message is returned. `merge`:
   * an edit of the object the action right before its place edits at the same time is merged into
   * that action (doc/mergeEdit.ts); its undo step still restores the scene before this edit.
   * `confirm`, called at the edit's turn right before it is sent (so a frame it asks for is the state
   * before the edit), gives the message shown once the edit is applied (editor.ts, doc/editConfirm.ts).
   */
  async edit(actions: Action[], merge = false, confirm?: () => Promise<string>): Promise<string | null> {
    const err = await this.changes.ticketed(async (ticket) => {
      const before = this.doc;
      let said: Promise<string | null> | null = null;
      const behind = this.notComputedYet(actions);
      if (behind !== null) return this.fail(behind);
      try {
        this.unconfirmed = before;
        said = confirm?.().catch(() => null) ?? null;
        const applied = this.client.apply(actions, merge);
        this.takeBackIfUndone(ticket);
        await applied;
      } catch (e) {
        // Taken back by an Undo during its check: that Undo says so.
        if (await this.tookBack(ticket)) return UNDONE_DURING_CHECK;
        // The engine names a later action by its index in the list before this edit (Timeline.apply);
        // with several actions, the later ones meet a list holding the earlier ones.
        return actions.length === 1 ? this.failNaming(e, before.actions, actions[0]) : this.fail(e);
      } finally {
        this.unconfirmed = null;
      }
      this.history.setState(record(this.history.getState(), before));
      this.names.left(before);
      this.ui.setState({ message: null });
      const text = await said;
      if (text) this.info(text);
      return null;
    });
    if (err !== null) return err;
    await this.ensureAhead();
    return null;
  }

  /**
   * Replaces a host that stopped answering (a computation that runs away) with a fresh one holding
   * the same scene; the history and the current time are kept.
   */
  async restartEngine(): Promise<void> {
    if (!this.portFactory) return;
    // Not queued behind pending changes: they may be waiting for the host that stopped answering
    // (replacePort rejects them).
    const doc = this.unconfirmed ?? this.doc;
    this.client.replacePort(this.portFactory());
    try {
      // The new host starts with no history: compute up to the current time and the Calculation
      // panel's seconds past it (not the old horizon, which the runaway computation may have set).
      await this.client.load(doc, this.keepTo());
    } catch (e) {
      this.fail(e);
      return;
    }
    this.info("The engine was restarted.");
    await this.afterReload();
  }
}
