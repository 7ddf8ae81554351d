/**
 * EditorSession: the base of Editor (editor.ts) that owns the scene session. It holds the
 * TimelineClient (the scene lives in the worker's Timeline), the UI store (time, speed, selection...)
 * and the undo history (whole scenes; only edits are recorded: a drag ends in one action, scrubbing,
 * speed and selection are never recorded). It loads scenes, applies edits as undo steps, undoes and
 * redoes them, computes ahead after each (Calculation settings) and restarts a host that stopped
 * answering. Methods that can fail resolve to the engine's message (null on success) and show it in
 * the UI.
 */

import { EMPTY_HISTORY, type History, record, redo, undo } from "./doc/history";
import { type ObjectKind, renameObject } from "./doc/rename";
import type { Action, SceneFile, Until } from "./engineTypes";
import type { TimelineClient } from "./remote/client";
import type { Port } from "./remote/protocol";
import { createStore, type Store } from "./store/createStore";
import type { UiStore } from "./store/uiStore";

export class EditorSession {
  readonly history: Store<History> = createStore<History>(EMPTY_HISTORY);
  /** Makes a fresh host (a new Web Worker) for restartEngine; null where none can be made. */
  portFactory: (() => Port) | null = null;

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
      const h = Number(info.horizon.toPrecision(6));
      this.ui.setState({
        message: { text: `The computation stopped at t = ${h} s: ${stopped}`, tone: "error" },
      });
    });
  }

  get doc(): SceneFile {
    return this.client.getSnapshot().doc!;
  }

  protected fail(e: unknown): string {
    const text = e instanceof Error ? e.message : String(e);
    this.ui.setState({ message: { text, tone: "error" } });
    return text;
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

  /** After reloading at the same time (undo, redo, rename): recomputes at least the old horizon. */
  protected async recompute(oldHorizon: number): Promise<void> {
    const c = this.ui.getState().calc;
    const target = Math.max(oldHorizon, this.now() + (c.useTime ? c.seconds : 0));
    if (target > 0)
      await this.client.compute({ time: target }).catch((e) => {
        this.fail(e);
      });
    else await this.computeAhead();
  }

  cancelCompute(): void {
    this.client.cancel().catch((e) => this.fail(e));
  }

  /** Loads a scene (preset, paste, file, URL). Invalid scenes are refused and the current one kept. */
  async loadScene(
    scene: SceneFile,
    options: { undoable?: boolean; fit?: boolean; keepTime?: boolean } = {},
  ): Promise<string | null> {
    const before = this.doc;
    const oldHorizon = this.client.getSnapshot().horizon;
    try {
      await this.client.load(scene);
    } catch (e) {
      return this.fail(e);
    }
    if (options.undoable !== false) this.history.setState(record(this.history.getState(), before));
    this.ui.setState((s) => ({
      t: options.keepTime ? s.t : 0,
      playing: options.keepTime ? s.playing : false,
      selection: options.keepTime ? s.selection : null,
      highlight: [],
      message: null,
      fitRequest: options.fit === false ? s.fitRequest : s.fitRequest + 1,
    }));
    if (options.keepTime) await this.recompute(oldHorizon);
    else await this.computeAhead();
    return null;
  }

  /** Applies edits as one undo step; on error nothing changes and the message is returned. */
  async edit(actions: Action[]): Promise<string | null> {
    const before = this.doc;
    try {
      await this.client.apply(actions);
    } catch (e) {
      return this.fail(e);
    }
    this.history.setState(record(this.history.getState(), before));
    this.ui.setState({ message: null });
    await this.ensureAhead();
    return null;
  }

  /** Replaces the action list as one undo step (renames, and other whole-scene rewrites). */
  rewrite(scene: SceneFile): Promise<string | null> {
    return this.loadScene(scene, { fit: false, keepTime: true });
  }

  /** Renames a body, line or point in the whole action list (one undo step). */
  async rename(kind: ObjectKind, from: string, to: string): Promise<string | null> {
    let scene: SceneFile;
    try {
      scene = renameObject(this.doc, kind, from, to);
    } catch (e) {
      return this.fail(e);
    }
    const err = await this.rewrite(scene);
    if (err === null) this.ui.setState({ selection: { kind, id: to } });
    return err;
  }

  async undo(): Promise<void> {
    const u = undo(this.history.getState(), this.doc);
    if (!u) return;
    await this.restore(u.scene, u.history);
  }

  async redo(): Promise<void> {
    const r = redo(this.history.getState(), this.doc);
    if (!r) return;
    await this.restore(r.scene, r.history);
  }

  private async restore(scene: SceneFile, history: History): Promise<void> {
    const oldHorizon = this.client.getSnapshot().horizon;
    try {
      await this.client.load(scene);
    } catch (e) {
      this.fail(e);
      return;
    }
    this.history.setState(history);
    this.ui.setState({ message: null });
    await this.recompute(oldHorizon);
  }

  /**
   * Replaces a host that stopped answering (a computation that runs away) with a fresh one holding
   * the same scene; the history and the current time are kept.
   */
  async restartEngine(): Promise<void> {
    if (!this.portFactory) return;
    const doc = this.doc;
    const oldHorizon = this.client.getSnapshot().horizon;
    this.client.replacePort(this.portFactory());
    try {
      await this.client.load(doc);
    } catch (e) {
      this.fail(e);
      return;
    }
    this.info("The engine was restarted.");
    await this.recompute(Math.min(oldHorizon, this.now()));
  }
}
