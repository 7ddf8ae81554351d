/**
 * Editor: the one object that turns user intentions into timeline requests. It owns the
 * TimelineClient (the scene lives in the worker's Timeline), the UI store (time, speed, selection...)
 * and the undo history (whole scenes; only edits are recorded: a drag ends in one action, scrubbing,
 * speed and selection are never recorded). Every edit is an action stamped with the current time.
 * Methods that can fail resolve to the engine's message (null on success) and show it in the UI.
 */

import { EMPTY_HISTORY, type History, record, redo, undo } from "./doc/history";
import { nextFreeId } from "./doc/ids";
import { type ObjectKind, renameObject } from "./doc/rename";
import type { Action, SceneFile, Until, Vec2 } from "./engineTypes";
import type { TimelineClient } from "./remote/client";
import type { Port } from "./remote/protocol";
import { createStore, type Store } from "./store/createStore";
import type { UiStore } from "./store/uiStore";

/** Velocity given by a cue strike, per world unit of offset between the click and the disc centre (1/s). */
export const STRIKE_RATE = 4;

export const EMPTY_SCENE: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [],
};

export class Editor {
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

  private fail(e: unknown): string {
    const text = e instanceof Error ? e.message : String(e);
    this.ui.setState({ message: { text, tone: "error" } });
    return text;
  }

  info(text: string): void {
    this.ui.setState({ message: { text, tone: "info" } });
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
  private async ensureAhead(): Promise<void> {
    const c = this.ui.getState().calc;
    const h = this.client.getSnapshot().horizon;
    if (c.useTime && !c.useEvents && h >= this.now() + c.seconds) return;
    await this.computeAhead();
  }

  /** After reloading at the same time (undo, redo, rename): recomputes at least the old horizon. */
  private async recompute(oldHorizon: number): Promise<void> {
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

  // ---- edits at the current time -------------------------------------------------------------

  private now(): number {
    return this.ui.getState().t;
  }

  /** Edits carry no `until`: the host computes ahead in slices (Calculation settings) after them. */
  private stamp<A extends Action>(a: A): A {
    return a;
  }

  /** Adds a disc and selects it (a refused disc selects nothing). */
  async addBody(x: number, y: number, r: number, m = 1, v: Vec2 = [0, 0]): Promise<string | null> {
    const id = nextFreeId("b", this.client.latestFrame?.ids ?? [], this.doc.actions);
    const err = await this.edit([
      this.stamp({ time: this.now(), type: "addBody", id, x, y, r, m, mu: 0, v }),
    ]);
    if (err === null) this.ui.setState({ selection: { kind: "body", id } });
    return err;
  }

  addLine(p1: Vec2, p2: Vec2, kind: "line" | "ray" | "segment"): Promise<string | null> {
    const id = nextFreeId("l", this.client.latestFrame?.lines.map((l) => l.id) ?? [], this.doc.actions);
    return this.edit([this.stamp({ time: this.now(), type: "addLine", id, p1, p2, kind })]);
  }

  addPoint(p: Vec2): Promise<string | null> {
    const id = nextFreeId("p", this.client.latestFrame?.points.map((q) => q.id) ?? [], this.doc.actions);
    return this.edit([this.stamp({ time: this.now(), type: "addPoint", id, p })]);
  }

  moveBody(id: string, x: number, y: number): Promise<string | null> {
    return this.edit([this.stamp({ time: this.now(), type: "updateBody", id, x, y })]);
  }

  giveVelocity(id: string, v: Vec2): Promise<string | null> {
    return this.edit([this.stamp({ time: this.now(), type: "giveVelocity", id, v })]);
  }

  /** A cue strike: velocity away from the click point, STRIKE_RATE per unit of offset. */
  strike(id: string, centre: Vec2, click: Vec2): Promise<string | null> {
    const v: Vec2 = [(centre[0] - click[0]) * STRIKE_RATE, (centre[1] - click[1]) * STRIKE_RATE];
    return this.giveVelocity(id, v);
  }

  updateBody(id: string, patch: { x?: number; y?: number; v?: Vec2; r?: number; m?: number; mu?: number }) {
    return this.edit([this.stamp({ time: this.now(), type: "updateBody", id, ...patch })]);
  }

  updateLine(id: string, patch: { p1?: Vec2; p2?: Vec2; kind?: "line" | "ray" | "segment" }) {
    return this.edit([this.stamp({ time: this.now(), type: "updateLine", id, ...patch })]);
  }

  updatePoint(id: string, p: Vec2) {
    return this.edit([this.stamp({ time: this.now(), type: "updatePoint", id, p })]);
  }

  setGlobal(patch: { g?: number; gravity?: Vec2 }) {
    return this.edit([this.stamp({ time: this.now(), type: "setGlobal", ...patch })]);
  }

  /** Removes the selected body, line or point at the current time. */
  async deleteSelection(): Promise<string | null> {
    const sel = this.ui.getState().selection;
    if (!sel) return null;
    const type = sel.kind === "body" ? "removeBody" : sel.kind === "line" ? "removeLine" : "removePoint";
    const err = await this.edit([this.stamp({ time: this.now(), type, id: sel.id })]);
    if (err === null) this.ui.setState({ selection: null });
    return err;
  }

  clear(): Promise<string | null> {
    return this.loadScene({ ...EMPTY_SCENE, g: this.doc.g, gravity: this.doc.gravity });
  }

  // ---- time ------------------------------------------------------------------------------------

  setTime(t: number): void {
    const h = this.client.getSnapshot().horizon;
    this.ui.setState({ t: Math.min(Math.max(t, 0), h) });
  }

  /**
   * Goes to time t (a typed time). Past the horizon it computes up to t first and then goes there
   * (cut to the horizon if that computation is cancelled or refused). When the user moves the time
   * or edits the scene while it computes, the time stays where they are.
   */
  async goTo(t: number): Promise<void> {
    const h = this.client.getSnapshot().horizon;
    if (!(t > h)) {
      this.setTime(t);
      return;
    }
    this.ui.setState({ playing: false });
    const from = this.ui.getState().t;
    const docRevision = this.client.getSnapshot().docRevision;
    try {
      await this.client.compute({ time: t - h });
    } catch (e) {
      this.fail(e);
      return;
    }
    await this.whenComputed();
    if (this.ui.getState().t !== from || this.client.getSnapshot().docRevision !== docRevision) return;
    this.setTime(t);
  }

  /** Resolves when the worker runs no computation. */
  private whenComputed(): Promise<void> {
    return new Promise((resolve) => {
      const check = () => {
        if (this.client.getSnapshot().computing !== null) return;
        off();
        resolve();
      };
      const off = this.client.subscribe(check);
      check();
    });
  }

  /** Steps to the next or previous event; when there is none, says so. */
  async stepEvent(direction: 1 | -1): Promise<void> {
    const t = this.now();
    const next = direction > 0 ? await this.client.nextEvent(t) : await this.client.prevEvent(t);
    if (next !== null) this.ui.setState({ t: next, playing: false });
    else {
      const at = Number(t.toPrecision(6));
      const h = Number(this.client.getSnapshot().horizon.toPrecision(6));
      this.info(
        direction > 0
          ? `No event after t = ${at} s up to the computed horizon (${h} s).`
          : `No event before t = ${at} s.`,
      );
    }
  }

  togglePlay(): void {
    const s = this.ui.getState();
    this.ui.setState({ playing: !s.playing });
  }

  setSpeed(speed: number): void {
    if (!Number.isFinite(speed)) return;
    this.ui.setState({ speed: Math.round(speed * 1000) / 1000 });
  }
}
