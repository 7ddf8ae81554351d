/**
 * EditorSession: the base of Editor (editor.ts) that owns the scene session. It holds the
 * TimelineClient (the scene lives in the worker's Timeline), the UI store (time, speed, selection...)
 * and the undo history (whole scenes; only edits are recorded: a drag ends in one action, scrubbing,
 * speed and selection are never recorded). It loads scenes, applies edits as undo steps, undoes and
 * redoes them (editorUndo.ts), computes ahead after each (Calculation settings) and restarts a host
 * that stopped answering. Methods that can fail resolve to the engine's message (null on success)
 * and show it in the UI. Changes of the scene (loads, edits, undo, redo) run strictly one after
 * another; each undoable change gets a ticket when asked (doc/undoIntents.ts), so an Undo asked
 * while it is still queued or checked is bound to it. An edit, rewrite or rename refused because a
 * later action would become invalid (the engine's path `actions[i]`) also says which action that
 * is (doc/actionRefs.ts).
 */

import { explainRefusal } from "./doc/actionRefs";
import { EMPTY_HISTORY, type History, record } from "./doc/history";
import { type ObjectKind, renameObject } from "./doc/rename";
import { changeAsked, type Intents, isUndone, NO_INTENTS, type Ticket } from "./doc/undoIntents";
import type { Action, SceneFile, Until } from "./engineTypes";
import type { TimelineClient } from "./remote/client";
import { type Port, UNDONE_DURING_CHECK } from "./remote/protocol";
import { createStore, type Store } from "./store/createStore";
import type { UiStore } from "./store/uiStore";

/** A time as messages write it (6 significant digits). */
export const shown = (t: number): number => Number(t.toPrecision(6));

export class EditorSession {
  readonly history: Store<History> = createStore<History>(EMPTY_HISTORY);
  /** Undo and Redo as the user asked them, over `history`, while changes are queued (undoIntents.ts). */
  readonly intents: Store<Intents> = createStore<Intents>(NO_INTENTS);
  /** Scene changes queued or running (intents are cleared when none is left). */
  private queued = 0;
  /** The take-back asked for a running change an Undo is bound to (client.takeBack). */
  private readonly takeBacks = new WeakMap<Ticket, Promise<SceneFile | null>>();
  /** Makes a fresh host (a new Web Worker) for restartEngine; null where none can be made. */
  portFactory: (() => Port) | null = null;
  /** The tail of the queue of scene changes (see serial). */
  private changes: Promise<unknown> = Promise.resolve();
  /**
   * The scene before a change the host has not answered yet (an edit or a rewrite whose later
   * actions it is still checking; its doc already shows the change): what a restarted engine loads,
   * since the change is answered "engine restarted" and never recorded.
   */
  protected unconfirmed: SceneFile | null = null;

  constructor(
    readonly client: TimelineClient,
    readonly ui: UiStore,
  ) {
    // A computation the engine refused to continue (a Zeno state): say why the horizon stops there.
    let stopped: string | null = null;
    client.subscribe(() => {
      const info = client.getSnapshot();
      if (info.stopped === stopped) return;
      stopped = info.stopped;
      if (stopped === null) return;
      const h = shown(info.horizon);
      this.ui.setState({
        message: { text: `The computation stopped at t = ${h} s: ${stopped}`, tone: "error" },
      });
    });
  }

  get doc(): SceneFile {
    return this.client.getSnapshot().doc!;
  }

  /**
   * Runs `change` once every scene change queued before it has been applied and recorded, so each
   * one reads the scene and the history its predecessors left. Only the change itself is queued:
   * the computing ahead that follows it is not waited for.
   */
  protected serial<T>(change: () => Promise<T>): Promise<T> {
    this.queued++;
    const run = this.changes.then(change).finally(() => {
      // Nothing queued: the history recorded is the history the user asked for.
      if (--this.queued === 0) this.intents.setState(NO_INTENTS);
    });
    this.changes = run.catch(() => undefined);
    return run;
  }

  /**
   * `change` (an undoable change: it resolves to null or the message, after recording its undo
   * step) queued with a ticket taken now, which says what became of it (undoIntents.ts).
   */
  private ticketed(change: (ticket: Ticket) => Promise<string | null>): Promise<string | null> {
    const ticket: Ticket = { fate: "queued" };
    this.intents.setState(changeAsked(this.intents.getState(), ticket));
    return this.serial(async () => {
      ticket.fate = "running";
      try {
        const err = await change(ticket);
        if (ticket.fate === "running") ticket.fate = err === null ? "done" : "refused";
        return err;
      } finally {
        this.takeBacks.delete(ticket);
      }
    });
  }

  /**
   * Asks the host to take back the running change of `ticket` if an Undo is bound to it and its
   * later actions are being checked (an Undo during the check: the change goes, nothing else).
   */
  protected takeBackIfUndone(ticket: Ticket): void {
    if (ticket.fate !== "running" || this.takeBacks.has(ticket)) return;
    if (!isUndone(this.intents.getState(), ticket)) return;
    this.takeBacks.set(
      ticket,
      this.client.takeBack().catch(() => null),
    );
  }

  /** After the change of `ticket` was refused: whether an Undo took it back (its fate is then set). */
  private async tookBack(ticket: Ticket): Promise<boolean> {
    const scene = await (this.takeBacks.get(ticket) ?? null);
    if (scene === null) return false;
    ticket.fate = "takenBack";
    ticket.scene = scene;
    return true;
  }

  protected fail(e: unknown): string {
    const text = e instanceof Error ? e.message : String(e);
    this.ui.setState({ message: { text, tone: "error" } });
    return text;
  }

  /**
   * fail, the message saying which action the engine's `actions[i]` is; `actions` is the list its
   * index refers to (the scene before an edit, the scene given to a load).
   */
  protected failNaming(e: unknown, actions: readonly Action[]): string {
    const text = e instanceof Error ? e.message : String(e);
    const path = (e as { path?: unknown } | null)?.path;
    return this.fail(explainRefusal(text, typeof path === "string" ? path : null, actions));
  }

  info(text: string): void {
    this.ui.setState({ message: { text, tone: "info" } });
  }

  /** The current time (the UI store's). */
  protected now(): number {
    return this.ui.getState().t;
  }

  /** What "compute ahead" means with the current Calculation settings (null: until idle). */
  computeUntil(): Until | null {
    const c = this.ui.getState().calc;
    const u: Until = {};
    if (c.useTime) u.time = c.seconds;
    if (c.useEvents) u.events = c.events;
    return c.useTime || c.useEvents ? u : null;
  }

  computeAhead(): Promise<void> {
    return this.client.compute(this.computeUntil()).catch((e) => {
      this.fail(e);
    });
  }

  /** After an edit: computes ahead unless the horizon is already far enough past the current time. */
  protected async ensureAhead(): Promise<void> {
    const c = this.ui.getState().calc;
    const h = this.client.getSnapshot().horizon;
    if (c.useTime && !c.useEvents && h >= this.now() + c.seconds) return;
    await this.computeAhead();
  }

  /**
   * How far a reload at the current time (undo, redo, rename, restart) must compute at least: the
   * current time, and the Calculation panel's seconds past it. The host also brings back the
   * history the scene had before the load (protocol.ts, `load`'s keepTo).
   */
  protected keepTo(): number {
    const c = this.ui.getState().calc;
    return this.now() + (c.useTime ? c.seconds : 0);
  }

  /** After a reload at the current time: computes ahead when the host had nothing to bring back. */
  protected afterReload(): Promise<void> {
    const info = this.client.getSnapshot();
    return info.computing === null && info.horizon === 0 ? this.computeAhead() : Promise.resolve();
  }

  cancelCompute(): void {
    this.client.cancel().catch((e) => this.fail(e));
  }

  /** Loads a scene (preset, paste, file, URL). Invalid scenes are refused and the current one kept. */
  async loadScene(
    scene: SceneFile,
    options: { undoable?: boolean; fit?: boolean; keepTime?: boolean } = {},
  ): Promise<string | null> {
    const loaded =
      options.undoable === false
        ? await this.serial(() => this.loadNow(scene, options))
        : await this.ticketed((ticket) => this.loadNow(scene, options, false, ticket));
    return this.afterLoad(loaded, options);
  }

  /**
   * The queued part of loadScene: the load and its undo step; null, or the message. `naming`: a
   * refusal says which action the engine's `actions[i]` is (for rewrites of the current scene, whose
   * actions are in the Event log; not for a file, a paste or a preset).
   */
  private async loadNow(
    scene: SceneFile,
    options: { undoable?: boolean; fit?: boolean; keepTime?: boolean },
    naming = false,
    ticket: Ticket | null = null,
  ): Promise<string | null> {
    const before = this.doc;
    try {
      // A rewrite of the current scene is checked up to where its history reached before the
      // reply (a removed action could leave a later one invalid); until then it is unconfirmed.
      if (naming) this.unconfirmed = before;
      const loaded = this.client.load(scene, options.keepTime ? this.keepTo() : undefined, naming);
      if (ticket !== null) this.takeBackIfUndone(ticket);
      await loaded;
    } catch (e) {
      if (ticket !== null && (await this.tookBack(ticket))) return UNDONE_DURING_CHECK;
      // The engine names actions by their index in the list it was given.
      return naming ? this.failNaming(e, scene.actions) : this.fail(e);
    } finally {
      this.unconfirmed = null;
    }
    if (options.undoable !== false) this.history.setState(record(this.history.getState(), before));
    this.ui.setState((s) => ({
      t: options.keepTime ? s.t : 0,
      playing: options.keepTime ? s.playing : false,
      selection: options.keepTime ? s.selection : null,
      highlight: [],
      message: null,
      fitRequest: options.fit === false ? s.fitRequest : s.fitRequest + 1,
      // the Time slider's zoom was a window of the other scene's history
      timeWindow: options.keepTime ? s.timeWindow : null,
    }));
    return null;
  }

  /** The rest of loadScene, not queued: computing ahead. */
  private async afterLoad(loaded: string | null, options: { keepTime?: boolean }): Promise<string | null> {
    if (loaded !== null) return loaded;
    if (options.keepTime) await this.afterReload();
    else await this.computeAhead();
    return null;
  }

  /**
   * Why edits at these times must wait, or null. After an undo, a redo or a rename the history is
   * recomputed from the start while the current time stays; until the computation reaches it, the
   * canvas and the tables show the state at the horizon, not at the current time, and an edit would
   * be built from those values (a velocity typed in one cell keeps the other component shown).
   */
  private notComputedYet(actions: Action[]): string | null {
    const info = this.client.getSnapshot();
    const late = Math.max(...actions.map((a) => a.time));
    if (!(late > info.horizon)) return null;
    const at = shown(late);
    const now = shown(info.horizon);
    if (info.computing === null)
      return `The history reaches only t = ${now} s (its computation was cancelled): go to a computed time, or type t = ${at} s to compute up to it, then edit.`;
    return `The history is still being computed up to t = ${at} s (it reaches ${now} s): edit once it gets there.`;
  }

  /** Applies edits as one undo step; on error nothing changes and the message is returned. */
  async edit(actions: Action[]): Promise<string | null> {
    const err = await this.ticketed(async (ticket) => {
      const before = this.doc;
      const behind = this.notComputedYet(actions);
      if (behind !== null) return this.fail(behind);
      try {
        this.unconfirmed = before;
        const applied = this.client.apply(actions);
        this.takeBackIfUndone(ticket);
        await applied;
      } catch (e) {
        // Taken back by an Undo during its check: that Undo says so.
        if (await this.tookBack(ticket)) return UNDONE_DURING_CHECK;
        // The engine names a later action by its index in the list before this edit (Timeline.apply);
        // with several actions, the later ones meet a list holding the earlier ones.
        return actions.length === 1 ? this.failNaming(e, before.actions) : this.fail(e);
      } finally {
        this.unconfirmed = null;
      }
      this.history.setState(record(this.history.getState(), before));
      this.ui.setState({ message: null });
      return null;
    });
    if (err !== null) return err;
    await this.ensureAhead();
    return null;
  }

  /**
   * Replaces the action list as one undo step (renames, removing an action, other whole-scene
   * rewrites). `scene` may be a function of the current scene, called when the change's turn comes
   * (after the changes queued before it); one that throws refuses the rewrite with its message.
   */
  async rewrite(scene: SceneFile | ((doc: SceneFile) => SceneFile)): Promise<string | null> {
    const options = { fit: false, keepTime: true };
    const loaded = await this.ticketed(async (ticket) => {
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
    const loaded = await this.ticketed(async (ticket) => {
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
